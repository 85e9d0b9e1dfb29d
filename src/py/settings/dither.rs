//! `Dither`: dithering between neighbouring bands (`effects::dither`).

use pyo3::prelude::*;
use pyo3::types::PyString;

use super::{getters, settings_class};
use crate::error::{Error, Result};
use crate::py::args::{opt_number, optional, text, type_name, Obj};
use crate::py::errors::to_py;
use crate::render::effects::dither::{Dither, DitherPattern, DitherSpace};

/// Dithering between neighbouring bands (Borquez and Yepez): L.n + (t - 1/2) amount is banded,
/// t the pattern's threshold at the pixel. pattern: "bayer2", "bayer4" (default), "bayer8"
/// (ordered dithering) or "blue" (the R2 sequence, a blue-noise-like pattern). space: "screen"
/// (default, as in the paper: the pattern stays put while the object moves) or "object"
/// (anchored to the surface, so a turntable does not shimmer). amount: in L.n, 0 to 2 (default
/// 0.15). scale: pixels a pattern cell covers, 1 to 64 (default 1).
#[pyclass(name = "Dither", module = "toonmesh._core", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyDither {
    pub inner: Dither,
}

settings_class!(PyDither, Dither, "Dither", |d| d.validate(""));

#[pymethods]
impl PyDither {
    #[new]
    #[pyo3(signature = (pattern = None, *, space = None, amount = None, scale = None))]
    fn new(
        pattern: Obj<'_, '_>,
        space: Obj<'_, '_>,
        amount: Obj<'_, '_>,
        scale: Obj<'_, '_>,
    ) -> PyResult<Self> {
        (|| {
            let mut d = Dither::new(match optional("pattern", pattern, text)? {
                None => DitherPattern::Bayer4,
                Some(p) => DitherPattern::parse("pattern", &p)?,
            });
            if let Some(s) = optional("space", space, text)? {
                d.space = DitherSpace::parse("space", &s)?;
            }
            d.amount = opt_number("amount", amount)?.unwrap_or(d.amount);
            d.scale = opt_number("scale", scale)?.unwrap_or(d.scale);
            d.validate("")?;
            Ok(PyDither { inner: d })
        })()
        .map_err(to_py)
    }

    fn __repr__(&self) -> String {
        repr(&self.inner)
    }
}

getters!(PyDither {
    pattern -> &'static str = |d| d.pattern.name();
    space -> &'static str = |d| d.space.name();
    amount -> f64 = |d| d.amount;
    scale -> f64 = |d| d.scale;
});

pub fn repr(d: &Dither) -> String {
    format!(
        "Dither({:?}, space={:?}, amount={}, scale={})",
        d.pattern.name(),
        d.space.name(),
        d.amount,
        d.scale
    )
}

/// The `dither=` argument: None (none), a pattern name (its defaults) or a Dither.
pub fn dither_arg(obj: Obj<'_, '_>) -> Result<Option<Dither>> {
    let Some(o) = obj else { return Ok(None) };
    if let Ok(d) = o.cast::<PyDither>() {
        return Ok(Some(d.get().inner));
    }
    if o.is_instance_of::<PyString>() {
        return Ok(Some(Dither::new(DitherPattern::parse("dither", &text("dither", o)?)?)));
    }
    Err(Error::wrong_type(
        "dither",
        format!("expected a pattern name or a toonmesh.Dither, got {}", type_name(o)),
    ))
}
