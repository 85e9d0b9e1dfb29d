//! What a render reports besides its images.

use crate::render::color::Srgb;
use crate::render::effects::outlines::settings::ink_name;

/// One visible mesh-space polyline in pixel coordinates, its kind, and the width of its ink at
/// each point in pixels (its kind's width times the factors of `stroke_width`, as the line pass
/// draws it).
#[derive(Clone, Debug, PartialEq)]
pub struct Polyline {
    pub kind: usize,
    pub points: Vec<[f64; 2]>,
    pub widths: Vec<f64>,
}

/// Front ends receive it through its serde form, with the lines' kinds by name
/// (`line_kinds`); the lines' points and widths, which go to arrays, through `flat_lines`.
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct FrameReport {
    /// The frame's size in pixels.
    pub width: u32,
    pub height: u32,
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
    #[serde(rename = "line_kinds", serialize_with = "kind_names_of")]
    pub lines: Option<Vec<Polyline>>,
    /// Per line of `lines`, the `Lines` item it belongs to (its index among the scene's), None
    /// for a mesh's line.
    pub line_items: Option<Vec<Option<usize>>>,
    /// Each `Lines` item's ink as drawn: its sRGB colour and width in output pixels.
    pub line_inks: Vec<(Srgb, f32)>,
    /// Per mesh, whether the camera's passes skipped its inner sides (`render::culling`).
    pub culled: Vec<bool>,
}

/// Each line's kind by name (None without lines).
fn kind_names_of<S: serde::Serializer>(lines: &Option<Vec<Polyline>>, s: S) -> Result<S::Ok, S::Error> {
    let kinds = lines.as_ref().map(|all| all.iter().map(|l| ink_name(l.kind)).collect::<Vec<_>>());
    serde::Serialize::serialize(&kinds, s)
}

impl FrameReport {
    /// The lines as flat arrays: every point in order, where each line starts (then where the
    /// last ends) and each point's ink width (f32, as the images hold widths); None without
    /// lines.
    pub fn flat_lines(&self) -> Option<(Vec<[f64; 2]>, Vec<u32>, Vec<f32>)> {
        let all = self.lines.as_ref()?;
        let (mut points, mut starts, mut widths) = (Vec::new(), vec![0], Vec::new());
        for l in all {
            points.extend_from_slice(&l.points);
            widths.extend(l.widths.iter().map(|&w| w as f32));
            starts.push(points.len() as u32);
        }
        Some((points, starts, widths))
    }
}
