//! Which way is up: a scene's up axis, the frame of the views about it, and each mesh file
//! format's convention.
//!
//! A fitted camera (`camera::Placement::Fit`) looks at the scene from a three-quarter view about
//! the up axis and keeps it up in the image. Meshes keep their coordinates: only the view
//! depends on the axis. Where nothing names one, +y is up (the renderer's default, and glTF's).

use glam::DVec3;

use crate::error::{Error, Result};

crate::named_enum! {
    /// A world axis that is up.
    pub enum Axis {
        X = "x",
        Y = "y",
        Z = "z",
    }
}

/// The up axis of a scene whose meshes and options name none.
pub const DEFAULT_UP: Axis = Axis::Y;

/// The up axis of each mesh file format, by its suffix (lower case, without the dot): glTF and
/// GLB by the glTF specification (+y up), OBJ as Blender's importer reads it (-z forward, +y up),
/// STL as 3D-printing tools and Blender's importer take it (+z up, the build plate's normal),
/// PLY as Blender's importer reads it (+y forward, +z up), 3MF by its specification (+z up, the
/// build platform's normal). Other formats have no convention here: their up axis is
/// `DEFAULT_UP`.
pub const FILE_UP_AXES: &[(&str, Axis)] = &[
    ("glb", Axis::Y),
    ("gltf", Axis::Y),
    ("obj", Axis::Y),
    ("stl", Axis::Z),
    ("ply", Axis::Z),
    ("3mf", Axis::Z),
];

/// The three-quarter view of a fitted camera given no direction, in degrees: turned this far
/// from the front toward the side, and raised this far above the horizon. Framed as near as a
/// cube allows, the eye then sees its top at 11 degrees and its side at 15 (a view raised 16
/// degrees would see a cube's top edge-on from that near).
pub const THREE_QUARTER_TURN: f64 = 30.0;
pub const THREE_QUARTER_RISE: f64 = 25.0;

/// A scene no thicker than this share of its extent is flat (a plate, a sheet): a fitted camera
/// given no direction sees it from its front, never within 30 degrees of edge-on.
pub const FLAT_THICKNESS: f64 = 0.1;
pub const FLAT_MOST_OFF_NORMAL: f64 = 60.0;

/// A horizontal extent counts as the longest only when it exceeds the front axis's own by this
/// fraction: a scene about as wide as deep is seen from its canonical front.
pub const LONGER_BY: f64 = 0.01;

impl Axis {
    /// The unit vector along the axis.
    pub fn vector(self) -> DVec3 {
        match self {
            Axis::X => DVec3::X,
            Axis::Y => DVec3::Y,
            Axis::Z => DVec3::Z,
        }
    }
}

/// An up direction's views: `side` and `front` horizontal, with side x up = front (right-handed),
/// so that a front view looks along -front with `side` to the right.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    pub side: DVec3,
    pub up: DVec3,
    pub front: DVec3,
}

impl Frame {
    /// The canonical frame of a unit up direction: for +y up the front is +z (side +x); for +z
    /// up the front is -y (side +x), as Blender's front view; for +x up the front is +y (side
    /// +z). An up direction between axes takes the frame of the axis nearest it, its side made
    /// horizontal.
    pub fn canonical(up: DVec3) -> Frame {
        let a = up.abs();
        let side = if a.y >= a.x && a.y >= a.z || a.z >= a.x && a.z > a.y { DVec3::X } else { DVec3::Z };
        let side = (side - up * side.dot(up)).normalize();
        Frame { side, up, front: side.cross(up) }
    }

    /// This frame turned by `degrees` about up (counter-clockwise seen from above).
    pub fn turned(self, degrees: f64) -> Frame {
        let (s, c) = degrees.to_radians().sin_cos();
        let side = self.side * c - self.front * s;
        Frame { side, up: self.up, front: side.cross(self.up) }
    }

    /// The frame that looks across the longest horizontal extent of `points`: the canonical one,
    /// or turned a quarter when the scene reaches further along its front than along its side
    /// (by more than `LONGER_BY`), so that the long side faces the camera.
    pub fn across(up: DVec3, points: &[DVec3]) -> Frame {
        let frame = Frame::canonical(up);
        let extent = |axis: DVec3| {
            let (lo, hi) = points.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p.dot(axis)), hi.max(p.dot(axis)))
            });
            hi - lo
        };
        if extent(frame.front) > extent(frame.side) * (1.0 + LONGER_BY) {
            frame.turned(90.0)
        } else {
            frame
        }
    }

    /// How far the three-quarter view looks from the front, in radians (38 degrees): a flat
    /// scene seen too near edge-on is seen this far from its normal instead.
    pub fn three_quarter_off_front() -> f64 {
        (THREE_QUARTER_TURN.to_radians().cos() * THREE_QUARTER_RISE.to_radians().cos()).acos()
    }

    /// The unit direction from the scene toward the eye of the three-quarter view: from the
    /// front, `THREE_QUARTER_TURN` toward the side and `THREE_QUARTER_RISE` above.
    pub fn three_quarter(self) -> DVec3 {
        let (ts, tc) = THREE_QUARTER_TURN.to_radians().sin_cos();
        let (rs, rc) = THREE_QUARTER_RISE.to_radians().sin_cos();
        (self.side * ts + self.front * tc) * rc + self.up * rs
    }
}

/// The up axis of a file with this suffix (see `FILE_UP_AXES`), or None.
pub fn file_up_axis(suffix: &str) -> Option<Axis> {
    let s = suffix.trim_start_matches('.').to_ascii_lowercase();
    FILE_UP_AXES.iter().find(|(name, _)| *name == s).map(|&(_, a)| a)
}

/// The up axis of a scene: `given` (the render's `up`), else the one its meshes name (`named`:
/// each mesh's, None where it names none), which must agree, else `DEFAULT_UP`.
pub fn scene_up(given: Option<Axis>, named: impl IntoIterator<Item = Option<Axis>>) -> Result<Axis> {
    if let Some(a) = given {
        return Ok(a);
    }
    let mut found: Option<(usize, Axis)> = None;
    for (i, a) in named.into_iter().enumerate() {
        match (a, found) {
            (Some(a), None) => found = Some((i, a)),
            (Some(a), Some((j, b))) if a != b => {
                return Err(Error::invalid(
                    "up",
                    format!(
                        "meshes[{j}] has up axis {} and meshes[{i}] has {}: give up= to choose one",
                        b.name(),
                        a.name()
                    ),
                ))
            }
            _ => {}
        }
    }
    Ok(found.map_or(DEFAULT_UP, |(_, a)| a))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_are_right_handed_and_match_blender_s_front_views() {
        for (up, side, front) in
            [(DVec3::Y, DVec3::X, DVec3::Z), (DVec3::Z, DVec3::X, -DVec3::Y), (DVec3::X, DVec3::Z, DVec3::Y)]
        {
            let f = Frame::canonical(up);
            assert!((f.side - side).length() < 1e-12 && (f.front - front).length() < 1e-12, "{f:?}");
            assert!((f.side.cross(f.up) - f.front).length() < 1e-12);
        }
    }

    #[test]
    fn the_view_looks_across_the_longest_horizontal_extent() {
        // long along z with y up: turned a quarter, so that the eye looks from +x across z
        let points = [DVec3::new(-1.0, 0.0, -5.0), DVec3::new(1.0, 3.0, 5.0)];
        let f = Frame::across(DVec3::Y, &points);
        assert!((f.front - DVec3::X).length() < 1e-12, "{f:?}");
        // as wide as deep: the canonical front
        let square = [DVec3::new(-1.0, 0.0, -1.0), DVec3::new(1.0, 9.0, 1.0)];
        assert_eq!(Frame::across(DVec3::Y, &square), Frame::canonical(DVec3::Y));
        let d = Frame::canonical(DVec3::Z).three_quarter();
        assert!((d.z - 25f64.to_radians().sin()).abs() < 1e-12 && d.y < -0.75 && d.x > 0.4, "{d:?}");
    }

    #[test]
    fn the_scene_s_up_is_given_or_agreed() {
        assert_eq!(scene_up(None, [None, None]).unwrap(), DEFAULT_UP);
        assert_eq!(scene_up(None, [None, Some(Axis::Z), Some(Axis::Z)]).unwrap(), Axis::Z);
        assert_eq!(scene_up(Some(Axis::X), [Some(Axis::Z)]).unwrap(), Axis::X);
        let e = scene_up(None, [Some(Axis::Y), None, Some(Axis::Z)]).unwrap_err().to_string();
        assert!(e.contains("meshes[0]") && e.contains("meshes[2]") && e.starts_with("up"), "{e}");
        assert_eq!(file_up_axis(".STL"), Some(Axis::Z));
        assert_eq!(file_up_axis("off"), None);
    }
}
