//! Vertex positions in the caller's precision (f32 or f64), owned or borrowed, so that work
//! generic over `Real` runs on them as given and gives them back in the same precision.

/// Vertex positions in the caller's precision.
pub enum Positions {
    F32(Vec<[f32; 3]>),
    F64(Vec<[f64; 3]>),
}

/// Borrowed vertex positions in the caller's precision.
#[derive(Clone, Copy)]
pub enum PositionsRef<'a> {
    F32(&'a [[f32; 3]]),
    F64(&'a [[f64; 3]]),
}

/// Runs `$body` with `$v` bound to the positions (a `PositionsRef`) in their own precision.
macro_rules! on_positions {
    ($p:expr, $v:ident => $body:expr) => {
        match $p {
            $crate::mesh::positions::PositionsRef::F32($v) => $body,
            $crate::mesh::positions::PositionsRef::F64($v) => $body,
        }
    };
}
#[cfg(feature = "python")]
pub(crate) use on_positions;

impl Positions {
    pub fn len(&self) -> usize {
        on_positions!(self.slices(), v => v.len())
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    pub fn slices(&self) -> PositionsRef<'_> {
        match self {
            Positions::F32(v) => PositionsRef::F32(v),
            Positions::F64(v) => PositionsRef::F64(v),
        }
    }
}
