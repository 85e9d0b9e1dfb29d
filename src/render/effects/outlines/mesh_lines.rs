//! The mesh-space lines of a view, found on the host before the frame is recorded (the
//! `silhouettes` step). Each mesh keeps its outline analysis (`MeshLines`, with the uploaded
//! mesh): the edge index, built on the first render that asks for mesh-space lines, and the
//! view-independent lines for each crease angle, so that each view only runs the silhouette
//! test.

use std::ops::Range;
use std::sync::{Arc, OnceLock};

use glam::{DMat4, DVec3};

use crate::edges::outlines::{LineKind, Outline, Statics};
use crate::edges::{EdgeIndex, View};
use crate::error::Result;
use crate::render::gpu_mesh::{GpuMesh, HostMesh};
use crate::render::graph::effect::{HostInputs, HostStep};
use crate::render::graph::report::FrameReport;
use crate::render::mesh_record::MeshRecord;
use crate::render::scene::camera::{direction_of, ResolvedCamera};

use super::settings::Outlines;

/// A mesh's outline analysis, kept with it.
#[derive(Default)]
pub struct MeshLines {
    /// Without and with welding, and the view-independent lines of each.
    indices: [OnceLock<Result<EdgeIndex>>; 2],
    statics: [Statics; 2],
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

    /// The lines of one view (`view` in the mesh's stored coordinates): silhouettes, then the
    /// cached view-independent lines, keeping the kinds `outlines` draws.
    pub fn outline(&self, host: &HostMesh, view: View, outlines: &Outlines) -> Result<Outline> {
        let index = self.index(host, outlines.weld)?;
        let statics = self.statics[outlines.weld as usize].at(outlines.crease_angle, || {
            crate::parallel::install(|| index.feature_edges(outlines.crease_angle))
        })?;
        let all = if outlines.styles[LineKind::Silhouette as usize].is_some() {
            let sil = crate::parallel::install(|| index.silhouette(view))?;
            statics.with_silhouettes(&sil)
        } else {
            (*statics).clone()
        };
        let (edges, kinds) =
            all.edges.iter().zip(&all.kinds).filter(|(_, k)| outlines.styles[**k as usize].is_some()).unzip();
        Ok(Outline { edges, kinds })
    }
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
    pub outlines: Vec<Outline>,
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
            let outline = MeshLines::of(rec).outline(&rec.host, view, &self.outlines)?;
            let first = lines.instances.len() as u32;
            let p = &rec.host.positions;
            lines.instances.extend(outline.edges.iter().zip(&outline.kinds).map(|(e, k)| LineInstance {
                a: p[e[0] as usize].map(|x| x as f32),
                kind: *k as u32,
                b: p[e[1] as usize].map(|x| x as f32),
                pad: 0,
            }));
            lines.draws.push(LineDraw { item: i, instances: first..lines.instances.len() as u32 });
            lines.outlines.push(outline);
        }
        // a slot is filled once per frame
        let _ = self.view.set(lines);
        Ok(())
    }
}
