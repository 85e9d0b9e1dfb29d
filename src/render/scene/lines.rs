//! Line segments placed in the world and drawn as ink (`toonmesh.Lines`: a wire, a path, a
//! file's line primitives): the user's own geometry, drawn whether or not the scene has
//! outlines, by the outlines' line pass (`effects::outlines`), hidden by the surfaces in front
//! of them under the scene's visibility rule.

use glam::{DMat4, DVec3};

use crate::edges::chains::chain_edges;
use crate::edges::outlines::LineKind;
use crate::error::{Error, Result};
use crate::render::color::{check_unit, Srgb};
use crate::render::effects::outlines::settings::{LineStyle, Outlines, WIDTH_RULE};

use super::check_transform;

/// One `Lines` item: points, the segments between them, its placement and its ink.
#[derive(Clone, Debug, PartialEq)]
pub struct LineSet {
    /// Points in the set's own coordinates (world units once placed).
    pub positions: Vec<[f64; 3]>,
    /// Pairs of indices into `positions`.
    pub segments: Vec<[u32; 2]>,
    /// Row-major 4x4 affine model -> world transform, as a mesh's.
    pub transform: [[f64; 4]; 4],
    /// The ink's sRGB colour; None: the outlines' (`common_ink`).
    pub color: Option<Srgb>,
    /// The ink's width in output pixels; None: the outlines'.
    pub width: Option<f32>,
}

impl LineSet {
    pub fn model_matrix(&self) -> DMat4 {
        DMat4::from_cols_array_2d(&self.transform).transpose()
    }

    /// Checks the set; `prefix` names it in errors (`"lines[0]"`).
    pub fn validate(&self, prefix: &str) -> Result<()> {
        if let Some(k) = self.positions.iter().position(|p| !p.iter().all(|v| v.is_finite())) {
            return Err(Error::invalid(format!("{prefix}.positions"), format!("row {k} is not finite")));
        }
        let n = self.positions.len();
        if let Some(k) = self.segments.iter().position(|s| s.iter().any(|&i| i as usize >= n)) {
            return Err(Error::out_of_range(
                format!("{prefix}.segments"),
                format!("row {k} {:?} indexes past the {n} positions", self.segments[k]),
            ));
        }
        check_transform(&format!("{prefix}.transform"), &self.transform)?;
        if let Some(c) = &self.color {
            check_unit(&format!("{prefix}.color"), c)?;
        }
        if let Some(w) = self.width {
            if !WIDTH_RULE.contains(w as f64) {
                return Err(Error::invalid(
                    format!("{prefix}.width"),
                    format!("must be a number of pixels {}, got {w}", WIDTH_RULE.text()),
                ));
            }
        }
        Ok(())
    }

    /// The set's ink: its own colour and width where given, else `common_ink(outlines)`'s.
    pub fn ink(&self, outlines: Option<&Outlines>) -> LineStyle {
        let common = common_ink(outlines);
        LineStyle {
            color: self.color.unwrap_or(common.color),
            width: self.width.unwrap_or(common.width),
            dash: 0.0,
        }
    }

    /// The segments joined into polylines where they meet end to end, in the set's own
    /// coordinates.
    pub fn polylines(&self) -> Vec<Vec<[f64; 3]>> {
        let (flat, starts) = chain_edges(&self.segments);
        starts
            .windows(2)
            .map(|w| flat[w[0] as usize..w[1] as usize].iter().map(|&v| self.positions[v as usize]).collect())
            .collect()
    }

    /// The box around the points the segments join, as placed in the world (None: no segment).
    pub fn world_box(&self) -> Option<[DVec3; 2]> {
        let m = self.model_matrix();
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for &i in self.segments.iter().flatten() {
            let p = m.transform_point3(DVec3::from_array(self.positions[i as usize]));
            (lo, hi) = (lo.min(p), hi.max(p));
        }
        (lo.is_finite() && hi.is_finite()).then_some([lo, hi])
    }
}

/// The outlines' ink that `Lines` items without their own colour or width take: the
/// silhouettes' style (else the first mesh-space kind drawn; else the default style).
pub fn common_ink(outlines: Option<&Outlines>) -> LineStyle {
    outlines
        .and_then(|o| {
            o.styles[LineKind::Silhouette as usize]
                .or_else(|| o.styles[..LineKind::COUNT].iter().find_map(|s| *s))
        })
        .unwrap_or_default()
}
