//! The borders between a scene's items: a boundary edge of one item that lies on a boundary
//! edge of another is no longer where a surface ends. Between items of different looks (their
//! material, or their colour and texture: the parts of a file with different materials) it is a
//! material border, as Blender's Line Art draws them. Between items of the same look it is a
//! seam inside one surface (a file stored as many pieces, triangle strips split apart): drawn
//! as the mesh's own edges would be, a silhouette where one side faces the camera and the other
//! does not, a ridge or valley where the two faces fold by more than the crease angle, and
//! nothing otherwise.

use std::collections::HashMap;
use std::sync::Arc;

use glam::DVec3;

use crate::edges::outlines::{LineKind, Outline};
use crate::error::Result;
use crate::mesh::dihedral::CreaseTest;
use crate::render::mesh_record::MeshRecord;
use crate::render::scene::camera::ResolvedCamera;
use crate::render::scene::SceneItem;

use super::settings::Outlines;

/// An item's boundary edge: the item, the edge's position in its outline, its ends as the
/// item's edge index numbers them, and in the world.
type Border = (usize, usize, [u32; 2], [DVec3; 2]);

/// Resolves the boundary edges that items share (see the module's comment) in each item's
/// `outlines`; the first item on a shared edge draws it, the others leave their copy out.
/// `face_on(item, edge)`: the corners of the face on a boundary edge of the item (numbered as
/// the item's outline numbers them).
pub fn shared_borders(
    items: &[SceneItem],
    records: &[Arc<MeshRecord>],
    cam: &ResolvedCamera,
    o: &Outlines,
    outlines: &mut [&mut Outline],
    face_on: impl Fn(usize, [u32; 2]) -> Option<([u32; 3], bool)>,
) -> Result<()> {
    let world = |i: usize, v: u32| {
        let p = records[i].gpu.placement;
        let stored = DVec3::from_array(records[i].host.positions[v as usize]);
        items[i].model_matrix().transform_point3(stored * p.scale + DVec3::from_array(p.origin))
    };
    let borders: Vec<Border> = outlines
        .iter()
        .enumerate()
        .flat_map(|(i, e)| {
            (0..e.len()).filter(move |&k| e.kinds[k] == LineKind::Boundary).map(move |k| (i, k, e.edges[k]))
        })
        .map(|(i, k, e)| (i, k, e, e.map(|v| world(i, v))))
        .collect();
    let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for p in borders.iter().flat_map(|b| b.3) {
        lo = lo.min(p);
        hi = hi.max(p);
    }
    // ends match to a millionth of the borders' extent
    let cell = ((hi - lo).length() * 1e-6).max(f64::MIN_POSITIVE);
    let key = |p: DVec3| ((p - lo) / cell).round().as_i64vec3().to_array();
    let edge_key = |e: &[DVec3; 2]| {
        let (a, b) = (key(e[0]), key(e[1]));
        (a.min(b), a.max(b))
    };
    // the borders at each place, of distinct items
    let mut places: HashMap<([i64; 3], [i64; 3]), Vec<usize>> = HashMap::new();
    for (n, b) in borders.iter().enumerate() {
        let at = places.entry(edge_key(&b.3)).or_default();
        if at.iter().all(|&m| borders[m].0 != b.0) {
            at.push(n);
        }
    }
    let crease = CreaseTest::new(o.crease_angle)?;
    let draws = |k: LineKind| o.styles[k as usize].is_some();
    // per item, each edge's new kind (None: left out)
    let mut changes: Vec<Vec<(usize, Option<LineKind>)>> = vec![Vec::new(); outlines.len()];
    for at in places.values().filter(|at| at.len() > 1) {
        let (first, rest) = (borders[at[0]], &at[1..]);
        let kind = match rest {
            [other] if same_look(items, records, first.0, borders[*other].0) => {
                let faces = [first, borders[*other]].map(|b| border_face(b, &face_on, &world));
                seam_kind(faces, first.3, cam, &crease).filter(|&k| draws(k))
            }
            _ if draws(LineKind::Material) => Some(LineKind::Material),
            _ => Some(LineKind::Boundary),
        };
        changes[first.0].push((first.1, kind));
        for &m in rest {
            changes[borders[m].0].push((borders[m].1, None));
        }
    }
    for (out, changed) in outlines.iter_mut().zip(changes) {
        if changed.is_empty() {
            continue;
        }
        let mut kinds: Vec<Option<LineKind>> = out.kinds.iter().copied().map(Some).collect();
        for (k, kind) in changed {
            kinds[k] = kind;
        }
        let (edges, kinds) = out.edges.iter().zip(kinds).filter_map(|(e, k)| k.map(|k| (*e, k))).unzip();
        **out = Outline { edges, kinds };
    }
    Ok(())
}

/// Whether two items are one surface to the lines: the same material, colour and texture.
fn same_look(items: &[SceneItem], records: &[Arc<MeshRecord>], i: usize, j: usize) -> bool {
    let look = |k: usize| records[k].gpu.albedo.as_ref().map(|a| a.look);
    items[i].material == items[j].material && look(i) == look(j)
}

/// The face on a border, in the world: its unit normal and the way it walks the border. None
/// for a face without area.
fn border_face(
    (i, _, edge, ends): Border,
    face_on: &impl Fn(usize, [u32; 2]) -> Option<([u32; 3], bool)>,
    world: &impl Fn(usize, u32) -> DVec3,
) -> Option<(DVec3, DVec3)> {
    let (face, forward) = face_on(i, edge)?;
    let corners = face.map(|v| world(i, v));
    let normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).try_normalize()?;
    Some((normal, if forward { ends[1] - ends[0] } else { ends[0] - ends[1] }))
}

/// A seam's kind from the faces on its two sides, as the mesh's own edge would be found:
/// silhouette, ridge or valley; None where it is no line (or a side has no area).
fn seam_kind(
    faces: [Option<(DVec3, DVec3)>; 2],
    ends: [DVec3; 2],
    cam: &ResolvedCamera,
    crease: &CreaseTest,
) -> Option<LineKind> {
    let [Some((n1, along1)), Some((n2, along2))] = faces else { return None };
    // consistently wound faces walk their shared edge opposite ways
    let n2 = if along1.dot(along2) > 0.0 { -n2 } else { n2 };
    let to_eye = if cam.orthographic { -cam.forward } else { cam.eye - (ends[0] + ends[1]) * 0.5 };
    if (n1.dot(to_eye) > 0.0) != (n2.dot(to_eye) > 0.0) {
        return Some(LineKind::Silhouette);
    }
    let (_, convex) = crease.crease(n1.to_array(), n2.to_array(), || along1.to_array())?;
    Some(if convex { LineKind::Ridge } else { LineKind::Valley })
}
