//! What a render reports besides its images.

/// One visible mesh-space polyline in pixel coordinates, its kind, and the width of its ink at
/// each point in pixels (its kind's width times the factors of `stroke_width`, as the line pass
/// draws it).
#[derive(Clone, Debug, PartialEq)]
pub struct Polyline {
    pub kind: usize,
    pub points: Vec<[f64; 2]>,
    pub widths: Vec<f64>,
}

/// Python receives it through its serde form; the lines, whose points go to NumPy, separately.
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct FrameReport {
    /// Every step that ran, in order (host steps included).
    pub passes: Vec<&'static str>,
    /// Seconds per step: GPU passes from timestamps where the device has them, host steps and
    /// `readback` (waiting for the frame and copying it out) by the wall clock, and `frame`,
    /// the whole render's wall time.
    pub timings: Vec<(&'static str, f64)>,
    /// Whether the GPU passes were timed on the GPU.
    pub gpu_timed: bool,
    /// The camera used: row-major world -> view and view -> clip matrices, clip distances.
    pub view: [[f64; 4]; 4],
    pub proj: [[f64; 4]; 4],
    pub near: f64,
    pub far: f64,
    /// The scene's up axis ("x", "y" or "z"), which fitted cameras keep up.
    pub up: &'static str,
    /// The visible mesh-space lines, when asked for.
    #[serde(skip)]
    pub lines: Option<Vec<Polyline>>,
    /// Per mesh, whether the camera's passes skipped its inner sides (`render::culling`).
    pub culled: Vec<bool>,
}
