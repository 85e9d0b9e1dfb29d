//! The mesh-space lines of a view, found on the host before the frame is recorded (the
//! `silhouettes` step). Each mesh keeps its outline analysis (`MeshLines`, with the uploaded
//! mesh): the edge index, built on the first render that asks for mesh-space lines, and the
//! view-independent lines for each crease angle, so that each view only runs the silhouette
//! test.

use std::collections::HashMap;
use std::ops::Range;
use std::sync::{Arc, Mutex, OnceLock};

use glam::{DMat4, DVec3};

use crate::cancel::Cancel;
use crate::edges::contours::ContourMesh;
use crate::edges::outlines::{LineKind, Outline, Statics};
use crate::edges::short_creases::drop_short_creases;
use crate::edges::zero_set::Polylines;
use crate::edges::{EdgeIndex, View};
use crate::error::Result;
use crate::mesh::Bounds;
use crate::render::gpu_mesh::{GpuMesh, HostMesh, NormalMode};
use crate::render::graph::effect::{HostInputs, HostStep};
use crate::render::graph::report::FrameReport;
use crate::render::mesh_record::MeshRecord;
use crate::render::scene::camera::{direction_of, ResolvedCamera};

use super::settings::{ContourRule, Outlines};

/// A mesh's outline analysis, kept with it.
#[derive(Default)]
pub struct MeshLines {
    /// Without and with welding, and the view-independent lines of each.
    indices: [OnceLock<Result<EdgeIndex>>; 2],
    statics: [Statics; 2],
    /// Without and with welding: the normals and curvature the contours are traced on.
    contours: [OnceLock<ContourMesh>; 2],
    /// The mesh split at the creases drawn under each (welding, crease angle, shortest crease).
    split: Mutex<HashMap<(bool, u64, u64), Arc<SplitContours>>>,
}

/// A mesh split at its drawn creases (smooth contours run between them) and those hard edges,
/// sorted, with its non-manifold edges: where the face-edge rule draws the silhouette.
struct SplitContours {
    mesh: ContourMesh,
    hard: Vec<[u32; 2]>,
}

/// One view's lines of a mesh: edges with their kinds, and the lines traced through faces
/// (smooth and suggestive contours) with theirs.
#[derive(Debug, Default)]
pub struct MeshOutline {
    pub edges: Outline,
    pub curves: Vec<(LineKind, Polylines)>,
}

impl MeshLines {
    /// The analysis kept with `rec`.
    pub fn of(rec: &MeshRecord) -> Arc<MeshLines> {
        rec.derived(MeshLines::default)
    }

    pub fn index(&self, host: &HostMesh, weld: bool) -> Result<&EdgeIndex> {
        self.indices[weld as usize]
            .get_or_init(|| crate::parallel::install(|| EdgeIndex::build(&host.positions, &host.faces, weld)))
            .as_ref()
            .map_err(Clone::clone)
    }

    fn contour_mesh(&self, host: &HostMesh, weld: bool) -> &ContourMesh {
        self.contours[weld as usize].get_or_init(|| {
            crate::parallel::install(|| ContourMesh::build(&host.positions, &host.faces, weld))
        })
    }

    /// The mesh split at the creases `statics` draws (and non-manifold edges), for the smooth
    /// rule: where a crease line is drawn, the silhouette follows the face edges.
    fn split(&self, host: &HostMesh, outlines: &Outlines, statics: &Outline) -> Result<Arc<SplitContours>> {
        let key = (outlines.weld, outlines.crease_angle.to_bits(), outlines.min_crease_length.to_bits());
        if let Some(s) = self.split.lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
            return Ok(s.clone());
        }
        let hard: Vec<[u32; 2]> = statics
            .edges
            .iter()
            .zip(&statics.kinds)
            .filter(|(_, k)| matches!(k, LineKind::Ridge | LineKind::Valley | LineKind::NonManifold))
            .map(|(e, _)| *e)
            .collect();
        let mesh = crate::parallel::install(|| {
            ContourMesh::split_at(&host.positions, &host.faces, outlines.weld, &hard)
        })?;
        let s = Arc::new(SplitContours { mesh, hard });
        self.split.lock().unwrap_or_else(|e| e.into_inner()).insert(key, s.clone());
        Ok(s)
    }

    /// The lines of one view (`view` in the mesh's stored coordinates): silhouettes (face edges,
    /// or smooth contours between creases and face edges on them, as `outlines.contours` says
    /// for a mesh drawn with `flat` normals or not), then the cached view-independent lines, and
    /// suggestive contours, keeping the kinds `outlines` draws.
    pub fn outline(
        &self,
        host: &HostMesh,
        flat: bool,
        view: View,
        outlines: &Outlines,
    ) -> Result<MeshOutline> {
        let draws = |k: LineKind| outlines.styles[k as usize].is_some();
        let index = self.index(host, outlines.weld)?;
        let min_crease = outlines.min_crease_length;
        let statics = self.statics[outlines.weld as usize].at(outlines.crease_angle, min_crease, || {
            let mut fe = crate::parallel::install(|| index.feature_edges(outlines.crease_angle))?;
            let diagonal = Bounds::of(index.positions()).diagonal();
            drop_short_creases(&mut fe, index.positions(), min_crease * diagonal);
            Ok(fe)
        })?;
        let mut curves = Vec::new();
        let all = if !draws(LineKind::Silhouette) {
            (*statics).clone()
        } else if outlines.contours.resolve(flat) == ContourRule::Faces {
            let sil = crate::parallel::install(|| index.silhouette(view))?;
            statics.with_silhouettes(&sil)
        } else {
            let split = self.split(host, outlines, &statics)?;
            let (smooth, sil) = crate::parallel::install(|| {
                rayon::join(|| split.mesh.smooth(view), || index.silhouette(view))
            });
            curves.push((LineKind::Silhouette, smooth));
            statics.with_silhouettes(&sorted_intersection(&sil?, &split.hard))
        };
        if draws(LineKind::Suggestive) {
            let m = self.contour_mesh(host, outlines.weld);
            let threshold = outlines.suggestive_threshold;
            let lines = crate::parallel::install(|| m.suggestive(view, threshold, Cancel::never()))?;
            curves.push((LineKind::Suggestive, lines));
        }
        let (edges, kinds) = all.edges.iter().zip(&all.kinds).filter(|(_, k)| draws(**k)).unzip();
        Ok(MeshOutline { edges: Outline { edges, kinds }, curves })
    }
}

/// The edges in both sorted lists.
fn sorted_intersection(a: &[[u32; 2]], b: &[[u32; 2]]) -> Vec<[u32; 2]> {
    let mut out = Vec::new();
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match a[i].cmp(&b[j]) {
            std::cmp::Ordering::Less => i += 1,
            std::cmp::Ordering::Greater => j += 1,
            std::cmp::Ordering::Equal => {
                out.push(a[i]);
                i += 1;
                j += 1;
            }
        }
    }
    out
}

/// The view of `cam` in a mesh's stored coordinates (for its silhouette test). The mesh's
/// placement is undone by subtracting and dividing, not by inverting a matrix whose
/// determinant may be out of float64's range.
pub fn stored_view(cam: &ResolvedCamera, model: DMat4, mesh: &GpuMesh) -> View {
    let to_model = model.inverse();
    let p = mesh.placement;
    if cam.orthographic {
        View::Direction(direction_of(to_model.transform_vector3(cam.forward)).to_array())
    } else {
        let e = (to_model.transform_point3(cam.eye) - DVec3::from_array(p.origin)) / p.scale;
        View::Eye(e.to_array())
    }
}

/// One mesh-space line: its end points in the mesh's stored coordinates and its kind (the
/// instance data of the lines pass).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LineInstance {
    pub a: [f32; 3],
    pub kind: u32,
    pub b: [f32; 3],
    pub pad: u32,
}

/// The lines of one scene item: a range of the frame's line instances.
#[derive(Clone, Debug)]
pub struct LineDraw {
    pub item: usize,
    pub instances: Range<u32>,
}

/// The lines of one view: each scene item's outline set, as the lines pass draws it (instances
/// and their ranges) and the visible-lines step chains it.
#[derive(Debug, Default)]
pub struct ViewLines {
    pub outlines: Vec<MeshOutline>,
    pub instances: Vec<LineInstance>,
    pub draws: Vec<LineDraw>,
}

/// Where the `silhouettes` step leaves a frame's lines for the passes and steps after it.
pub type ViewSlot = Arc<OnceLock<ViewLines>>;

/// The `silhouettes` step: every item's lines for this view.
#[derive(Debug)]
pub struct Silhouettes {
    pub outlines: Outlines,
    pub view: ViewSlot,
}

impl HostStep for Silhouettes {
    fn name(&self) -> &'static str {
        "silhouettes"
    }

    fn run(&self, cx: &HostInputs<'_>, _report: &mut FrameReport) -> Result<()> {
        let mut lines = ViewLines::default();
        for (i, (item, rec)) in cx.scene.scene.items.iter().zip(cx.records).enumerate() {
            let view = stored_view(cx.cam, item.model_matrix(), &rec.gpu);
            let flat = rec.gpu.normals == NormalMode::Flat;
            let outline = MeshLines::of(rec).outline(&rec.host, flat, view, &self.outlines)?;
            let first = lines.instances.len() as u32;
            let p = &rec.host.positions;
            let instance = |a: [f64; 3], b: [f64; 3], kind: LineKind| LineInstance {
                a: a.map(|x| x as f32),
                kind: kind as u32,
                b: b.map(|x| x as f32),
                pad: 0,
            };
            let edges = &outline.edges;
            lines.instances.extend(
                edges
                    .edges
                    .iter()
                    .zip(&edges.kinds)
                    .map(|(e, k)| instance(p[e[0] as usize], p[e[1] as usize], *k)),
            );
            for (kind, curves) in &outline.curves {
                for i in 0..curves.len() {
                    lines.instances.extend(curves.line(i).windows(2).map(|s| instance(s[0], s[1], *kind)));
                }
            }
            lines.draws.push(LineDraw { item: i, instances: first..lines.instances.len() as u32 });
            lines.outlines.push(outline);
        }
        // a slot is filled once per frame
        let _ = self.view.set(lines);
        Ok(())
    }
}
