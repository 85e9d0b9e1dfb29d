//! The mesh-space lines of a view, found on the host before the frame is recorded (the
//! `silhouettes` step). Each mesh keeps its outline analysis (`MeshLines`, with the uploaded
//! mesh): the edge index, built on the first render that asks for mesh-space lines, and the
//! view-independent lines for each crease angle, so that each view only runs the silhouette
//! test.

use std::collections::HashMap;
use std::ops::Range;
use std::sync::{Arc, Mutex, OnceLock, Weak};

use glam::{DMat4, DVec3};

use crate::cancel::Cancel;
use crate::edges::chains::chain_edges;
use crate::edges::coherence::Drawn;
use crate::edges::contours::ContourMesh;
use crate::edges::outlines::{LineKind, Outline, Statics};
use crate::edges::short_creases::keep_drawn_creases;
use crate::edges::zero_set::Polylines;
use crate::edges::{EdgeIndex, View};
use crate::error::Result;
use crate::mesh::back_to_back::without_back_to_back;
use crate::mesh::bvh::Bvh;
use crate::render::color::to_linear;
use crate::render::gpu_mesh::{GpuMesh, HostMesh, NormalMode};
use crate::render::mesh_record::MeshRecord;
use crate::render::scene::camera::{direction_of, ResolvedCamera};
use crate::render::scene::lines::LineSet;
use crate::render::scene::SceneItem;

use super::projection::{Projector, ScreenLine};
use super::settings::{ContourRule, Outlines, HIDDEN_KIND, LINES_KIND};
use super::shared_borders::shared_borders;
use super::stroke_width::{strength_factor, StrokeWidth};
use crate::render::scene::sequence::SequenceFrame;

/// A mesh's outline analysis, kept with it.
#[derive(Default)]
pub struct MeshLines {
    /// Without and with welding, and the view-independent lines of each.
    indices: [OnceLock<Result<EdgeIndex>>; 2],
    statics: [Statics; 2],
    /// Without and with welding: the normals and curvature the contours are traced on.
    contours: [OnceLock<ContourMesh>; 2],
    /// The mesh split at the creases drawn under each crease rule.
    split: Mutex<HashMap<SplitKey, Arc<SplitContours>>>,
    /// With welding, the faces less those back to back with another (`back_to_back::without_back_to_back`;
    /// None: all of them), decided with the welded index.
    back_to_back: OnceLock<Option<Vec<[u32; 3]>>>,
    /// The hierarchy of every face, in the stored coordinates: what exact visibility casts
    /// its rays against and intersection lines pair faces with.
    bvh: OnceLock<Bvh>,
    /// The last few intersection lines found with other meshes (`crossings_with`).
    crossings: Mutex<Vec<KeptCrossings>>,
}

/// Intersection lines kept beyond this many (other mesh, placement) pairs are forgotten, the
/// oldest first.
const KEPT_CROSSINGS: usize = 8;

/// Intersection lines with another mesh placed by `other_to_self` (its stored coordinates into
/// this mesh's, as bits: the camera plays no part), chained, in this mesh's stored coordinates.
struct KeptCrossings {
    other: Weak<MeshRecord>,
    other_to_self: [u64; 16],
    lines: Arc<Vec<Vec<[f64; 3]>>>,
}

/// Welding, then the bits of the crease angle, the shortest crease piece and the largest mean
/// turn of a piece.
type SplitKey = (bool, u64, u64, u64);

/// A mesh split at its drawn creases (smooth contours run between them) and those hard edges,
/// sorted, with its non-manifold edges: where the face-edge rule draws the silhouette.
pub struct SplitContours {
    pub mesh: ContourMesh,
    pub hard: Vec<[u32; 2]>,
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

    /// The hierarchy of the mesh's faces (built on the first call, in parallel).
    pub fn bvh(&self, host: &HostMesh) -> &Bvh {
        self.bvh.get_or_init(|| crate::parallel::install(|| Bvh::build(&host.positions, &host.faces)))
    }

    /// Every record's analysis with its hierarchy built (the meshes side by side, the first
    /// time): what the exact rule and the intersection lines read with `bvh`.
    pub fn with_hierarchies(records: &[Arc<MeshRecord>]) -> Vec<Arc<MeshLines>> {
        use rayon::prelude::*;
        let lines: Vec<Arc<MeshLines>> = records.iter().map(|r| MeshLines::of(r)).collect();
        crate::parallel::install(|| {
            lines.par_iter().zip(records).for_each(|(l, r)| {
                l.bvh(&r.host);
            })
        });
        lines
    }

    /// The intersection lines with `other` placed by `other_to_self`, found by `find` the first
    /// time (and again once forgotten: `KEPT_CROSSINGS`), so a still scene seen from many
    /// views finds them once.
    pub fn crossings_with(
        &self,
        other: &Arc<MeshRecord>,
        other_to_self: &DMat4,
        find: impl FnOnce() -> Vec<Vec<[f64; 3]>>,
    ) -> Arc<Vec<Vec<[f64; 3]>>> {
        let key = other_to_self.to_cols_array().map(f64::to_bits);
        let mine = |k: &KeptCrossings| {
            k.other_to_self == key && k.other.upgrade().is_some_and(|o| Arc::ptr_eq(&o, other))
        };
        if let Some(k) = self.crossings.lock().unwrap_or_else(|e| e.into_inner()).iter().find(|k| mine(k)) {
            return k.lines.clone();
        }
        let lines = Arc::new(find());
        let mut kept = self.crossings.lock().unwrap_or_else(|e| e.into_inner());
        kept.retain(|k| k.other.strong_count() > 0);
        if kept.len() >= KEPT_CROSSINGS {
            kept.remove(0);
        }
        kept.push(KeptCrossings { other: Arc::downgrade(other), other_to_self: key, lines: lines.clone() });
        lines
    }

    /// The index of the faces lines are found on (`faces`).
    pub fn index(&self, host: &HostMesh, weld: bool) -> Result<&EdgeIndex> {
        self.indices[weld as usize]
            .get_or_init(|| {
                crate::parallel::install(|| {
                    let index = EdgeIndex::build(&host.positions, &host.faces, weld)?;
                    // only faces back to back make non-manifold edges of a sheet
                    let kept = match index.weld_map() {
                        Some(map) if index.has_nonmanifold() => without_back_to_back(&host.faces, map)?,
                        _ => None,
                    };
                    let index = match &kept {
                        Some(faces) => EdgeIndex::build(&host.positions, faces, weld)?,
                        None => index,
                    };
                    if weld {
                        let _ = self.back_to_back.set(kept);
                    }
                    Ok(index)
                })
            })
            .as_ref()
            .map_err(Clone::clone)
    }

    /// The faces lines are found on: with welding, a sheet stored double-sided counts once.
    fn faces<'a>(&'a self, host: &'a HostMesh, weld: bool) -> &'a [[u32; 3]] {
        if weld && self.index(host, weld).is_ok() {
            if let Some(Some(faces)) = self.back_to_back.get() {
                return faces;
            }
        }
        &host.faces
    }

    fn contour_mesh(&self, host: &HostMesh, weld: bool) -> &ContourMesh {
        self.contours[weld as usize].get_or_init(|| {
            let faces = self.faces(host, weld);
            crate::parallel::install(|| ContourMesh::build(&host.positions, faces, weld))
        })
    }

    /// The mesh split at the creases `statics` draws (and non-manifold edges), for the smooth
    /// rule: where a crease line is drawn, the silhouette follows the face edges.
    fn split(&self, host: &HostMesh, outlines: &Outlines, statics: &Outline) -> Result<Arc<SplitContours>> {
        let key = (
            outlines.weld,
            outlines.crease_angle.to_bits(),
            outlines.min_crease_length.to_bits(),
            outlines.max_crease_turn.to_bits(),
        );
        if let Some(s) = self.split.lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
            return Ok(s.clone());
        }
        let mut hard: Vec<[u32; 2]> = statics
            .edges
            .iter()
            .zip(&statics.kinds)
            .filter(|(_, k)| matches!(k, LineKind::Ridge | LineKind::Valley | LineKind::NonManifold))
            .map(|(e, _)| *e)
            .collect();
        hard.sort_unstable();
        let mesh = crate::parallel::install(|| {
            ContourMesh::split_at(&host.positions, self.faces(host, outlines.weld), outlines.weld, &hard)
        })?;
        let s = Arc::new(SplitContours { mesh, hard });
        self.split.lock().unwrap_or_else(|e| e.into_inner()).insert(key, s.clone());
        Ok(s)
    }

    /// The view-independent lines (boundaries, creases, non-manifold edges) under the crease
    /// rule of `outlines`, found the first time and kept.
    pub fn statics(&self, host: &HostMesh, outlines: &Outlines) -> Result<Arc<Outline>> {
        let index = self.index(host, outlines.weld)?;
        let (min_crease, max_turn) = (outlines.min_crease_length, outlines.max_crease_turn);
        self.statics[outlines.weld as usize].at(outlines.crease_angle, min_crease, max_turn, || {
            let mut fe = crate::parallel::install(|| index.feature_edges(outlines.crease_angle))?;
            keep_drawn_creases(&mut fe, index.positions(), min_crease, max_turn);
            Ok(fe)
        })
    }

    /// What the smooth rule traces silhouettes on under `outlines` (`split`): the mesh split at
    /// the creases drawn, and the hard edges, where the face-edge rule draws them.
    pub fn split_contours(&self, host: &HostMesh, outlines: &Outlines) -> Result<Arc<SplitContours>> {
        let statics = self.statics(host, outlines)?;
        self.split(host, outlines, &statics)
    }

    /// The lines of one view (`view` in the mesh's stored coordinates): silhouettes (face edges,
    /// or smooth contours between creases and face edges on them, as `outlines.contours` says
    /// for a mesh drawn with `flat` normals or not), then the cached view-independent lines, and
    /// suggestive contours, keeping the kinds `outlines` draws. In a sequence of views,
    /// `sequence` holds the views before and after (in the same coordinates) and what the view
    /// before drew, and suggestive contours hold still across them (`edges::coherence`).
    pub fn outline(
        &self,
        host: &HostMesh,
        flat: bool,
        view: View,
        outlines: &Outlines,
        sequence: Option<(Option<View>, Option<View>, &mut Drawn)>,
    ) -> Result<MeshOutline> {
        let draws = |k: LineKind| outlines.styles[k as usize].is_some();
        let index = self.index(host, outlines.weld)?;
        let statics = self.statics(host, outlines)?;
        let mut curves = Vec::new();
        let all = if !draws(LineKind::Silhouette) {
            (*statics).clone()
        } else if outlines.contours.resolve(flat) == ContourRule::Faces {
            let sil = crate::parallel::install(|| index.silhouette(view))?;
            statics.with_silhouettes(&sil)
        } else {
            let split = self.split(host, outlines, &statics)?;
            let (smooth, sil) = crate::parallel::install(|| {
                rayon::join(|| split.mesh.smooth(view), || index.silhouette_among(view, &split.hard))
            });
            curves.push((LineKind::Silhouette, smooth));
            statics.with_silhouettes(&sil?)
        };
        if draws(LineKind::Suggestive) {
            let m = self.contour_mesh(host, outlines.weld);
            let threshold = outlines.suggestive_threshold;
            let smoothing = outlines.curvature_smoothing;
            let lines = crate::parallel::install(|| match sequence {
                Some((before, after, drawn)) => {
                    m.coherent_suggestive((before, view, after), threshold, smoothing, drawn, Cancel::never())
                }
                None => m.suggestive(view, threshold, smoothing, Cancel::never()),
            })?;
            curves.push((LineKind::Suggestive, lines));
        }
        // boundaries are kept for the borders between items found across the scene
        let keep = |k: LineKind| draws(k) || k == LineKind::Boundary;
        let (edges, kinds) = all.edges.iter().zip(&all.kinds).filter(|(_, k)| keep(**k)).unzip();
        Ok(MeshOutline { edges: Outline { edges, kinds }, curves })
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

/// One mesh-space line: its end points in the mesh's stored coordinates, its kind, and its width
/// factors at both ends (`stroke_width`): the instance data of the lines pass.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LineInstance {
    pub a: [f32; 3],
    /// The ink kind (`settings::kind_names`).
    pub kind: u32,
    pub b: [f32; 3],
    /// `EXACT` where visibility was decided on the host (the frame's lines); 0 for the drafts.
    pub flags: u32,
    pub scale: [f32; 2],
}

/// `LineInstance::flags`: the line is known to be visible (or drawn as hidden), so the lines
/// pass draws it without its depth test.
pub const EXACT: u32 = 1;
/// `LineInstance::flags`: the line is inked in its own colour and width (`FrameLine::ink`), solid,
/// and held against the surfaces only (a `Lines` item's, not a rim of a mesh).
pub const OWN_INK: u32 = 2;
/// `LineInstance::flags`: its points are in normalised view coordinates already (a `Lines`
/// item's), not a mesh's stored ones.
pub const IN_VIEW: u32 = 4;

impl LineInstance {
    /// Its vertex attributes, shader locations 0 to 3 (`LineIn` in `lines.wgsl`): the flags
    /// are the frame's (`FrameLine`).
    pub const ATTRIBUTES: [wgpu::VertexAttribute; 4] = [
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x3, offset: 0, shader_location: 0 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Uint32, offset: 12, shader_location: 1 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x3, offset: 16, shader_location: 2 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x2, offset: 32, shader_location: 3 },
    ];

    /// The line of `kind` from `a` to `b` (float64 points made float32), with the width factors
    /// `scale` at its ends.
    pub fn new(kind: LineKind, a: [f64; 3], b: [f64; 3], scale: [f32; 2]) -> Self {
        LineInstance::of_ink(kind as usize, a, b, scale)
    }

    /// The line of ink kind `ink` (`settings::kind_names`).
    pub fn of_ink(ink: usize, a: [f64; 3], b: [f64; 3], scale: [f32; 2]) -> Self {
        LineInstance { a: a.map(|x| x as f32), kind: ink as u32, b: b.map(|x| x as f32), flags: 0, scale }
    }
}

/// One line of a frame: the line, the distance along its stroke on screen at both ends
/// (output pixels at the frame's pixel ratio), where its dashes are measured from, and its own
/// ink where `OWN_INK` says so.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct FrameLine {
    pub line: LineInstance,
    pub along: [f32; 2],
    /// Linear rgb and the width in output pixels (`OWN_INK`); zeros otherwise.
    pub ink: [f32; 4],
}

impl FrameLine {
    /// Its vertex attributes: the line's, then the flags, the distances along and the own ink
    /// (`LineIn` in `lines.wgsl`, locations 4 to 6).
    pub const ATTRIBUTES: [wgpu::VertexAttribute; 7] = {
        let [a, kind, b, scale] = LineInstance::ATTRIBUTES;
        [
            a,
            kind,
            b,
            scale,
            wgpu::VertexAttribute {
                format: wgpu::VertexFormat::Uint32,
                offset: std::mem::offset_of!(LineInstance, flags) as u64,
                shader_location: 4,
            },
            wgpu::VertexAttribute {
                format: wgpu::VertexFormat::Float32x2,
                offset: std::mem::offset_of!(FrameLine, along) as u64,
                shader_location: 5,
            },
            wgpu::VertexAttribute {
                format: wgpu::VertexFormat::Float32x4,
                offset: std::mem::offset_of!(FrameLine, ink) as u64,
                shader_location: 6,
            },
        ]
    };

    /// The line as the lines pass draws it (its float32 points, width factors and distances
    /// along), projected.
    pub fn screen(&self, projector: &Projector) -> Option<ScreenLine> {
        let l = &self.line;
        let s = projector.project(l.a.map(|x| x as f64), l.b.map(|x| x as f64), l.kind as usize)?;
        Some(ScreenLine {
            scale: l.scale.map(|x| x as f64),
            along: self.along.map(|x| x as f64),
            exact: l.flags & EXACT != 0,
            own_width: (l.flags & OWN_INK != 0).then_some(self.ink[3] as f64),
            ..s
        })
    }
}

/// The lines of one scene item: a range of the frame's line instances.
#[derive(Clone, Debug)]
pub struct LineDraw {
    pub item: usize,
    pub instances: Range<u32>,
}

/// One polyline of a view's mesh-space lines: a chain of edges of one kind, or a curve traced
/// through faces, in the mesh's stored coordinates.
#[derive(Clone, Debug)]
pub struct Chain {
    pub kind: LineKind,
    pub points: Vec<[f64; 3]>,
    /// How strongly the line is there at each point, in [0, 1] (a suggestive contour fades in
    /// past its threshold); empty: fully.
    pub strength: Vec<f64>,
    /// Traced through faces (a contour), not along edges.
    pub traced: bool,
    /// How many surfaces hide it, where the exact rule decided (`occluded`); None: the lines
    /// pass decides against the frame's depth.
    pub occlusion: Option<u32>,
    /// A `Lines` item's line: its ink (linear rgb, width in pixels), its points in normalised
    /// view coordinates. None: a mesh's line, in its stored coordinates.
    pub own: Option<[f32; 4]>,
}

impl Chain {
    /// Its ink kind: its line kind (`LINES_KIND` for a `Lines` item's), or hidden lines' where
    /// surfaces hide it.
    pub fn ink(&self) -> usize {
        match self.occlusion {
            Some(q) if q > 0 => HIDDEN_KIND,
            _ if self.own.is_some() => LINES_KIND,
            _ => self.kind as usize,
        }
    }

    /// Its ink's width in pixels under `outlines` where it is visible.
    pub fn width(&self, outlines: &Outlines) -> f64 {
        match self.own {
            Some(_) => self.own_width(),
            None => outlines.styles[self.kind as usize].map_or(0.0, |s| s.width as f64),
        }
    }

    /// A `Lines` item's ink width in pixels (0 for a mesh's line).
    pub fn own_width(&self) -> f64 {
        self.own.map_or(0.0, |o| o[3] as f64)
    }
}

/// Each `Lines` item's polylines seen by `cam` (in normalised view coordinates, as the lines
/// pass draws them), in its ink (resolved when the scene was checked).
pub fn set_chains(sets: &[LineSet], cam: &ResolvedCamera) -> Vec<Vec<Chain>> {
    let view = cam.normalized_view();
    sets.iter()
        .map(|set| {
            let ink = set.ink(None);
            let [r, g, b] = to_linear(ink.color);
            let model_view = view * set.model_matrix();
            let seen = |p: &[f64; 3]| model_view.transform_point3(DVec3::from_array(*p)).to_array();
            set.polylines()
                .iter()
                .map(|points| Chain {
                    // a kind off the rim: the line is held against surfaces only
                    kind: LineKind::Ridge,
                    points: points.iter().map(seen).collect(),
                    strength: Vec::new(),
                    traced: false,
                    occlusion: None,
                    own: Some([r, g, b, ink.width]),
                })
                .collect()
        })
        .collect()
}

/// The lines of one view: each scene item's chains, as the lines pass draws them (instances and
/// their ranges) and the visible-lines step cuts them.
#[derive(Debug, Default)]
pub struct ViewLines {
    pub chains: Vec<Vec<Chain>>,
    pub instances: Vec<FrameLine>,
    pub draws: Vec<LineDraw>,
}

/// Where the `silhouettes` step leaves a frame's lines for the passes and steps after it.
pub type ViewSlot = Arc<OnceLock<ViewLines>>;

/// A mesh's lines of one view as chains: each kind's edges joined into polylines
/// (`edges::chains`), then the curves traced through faces.
pub fn chains(outline: &MeshOutline, positions: &[[f64; 3]]) -> Vec<Chain> {
    let edges = &outline.edges;
    let mut kinds: Vec<LineKind> = edges.kinds.clone();
    kinds.sort_unstable();
    kinds.dedup();
    let mut out = Vec::new();
    for kind in kinds {
        let of_kind: Vec<[u32; 2]> =
            edges.edges.iter().zip(&edges.kinds).filter(|(_, k)| **k == kind).map(|(e, _)| *e).collect();
        let (flat, starts) = chain_edges(&of_kind);
        for w in starts.windows(2) {
            let points = flat[w[0] as usize..w[1] as usize].iter().map(|&v| positions[v as usize]).collect();
            out.push(Chain { kind, points, strength: Vec::new(), traced: false, occlusion: None, own: None });
        }
    }
    for (kind, curves) in &outline.curves {
        out.extend((0..curves.len()).map(|i| Chain {
            kind: *kind,
            points: curves.line(i).to_vec(),
            strength: curves.line_strength(i).to_vec(),
            traced: true,
            occlusion: None,
            own: None,
        }));
    }
    out
}

/// The line instances of a mesh's chains, with each end's width factor from `rule`: the
/// distances along each chain and the depths are those of the chain projected by `projector`;
/// `reference` is the depth whose lines keep their width.
pub fn instances(
    chains: &[Chain],
    projector: &Projector,
    rule: &StrokeWidth,
    reference: f64,
) -> Vec<FrameLine> {
    let mut out = Vec::new();
    for c in chains {
        let n = c.points.len();
        let (mut along, mut depths) = (vec![0.0; n], vec![0.0; n]);
        let faded = c.strength.len() == n;
        for i in 1..n {
            let seen = projector.project(c.points[i - 1], c.points[i], 0);
            let (l, za, zb) = seen.map_or((0.0, 0.0, 0.0), |l| (l.length(), l.za, l.zb));
            along[i] = along[i - 1] + l;
            if i == 1 {
                depths[0] = za;
            }
            depths[i] = zb;
        }
        let closed = n > 2 && c.points[0] == c.points[n - 1];
        // a `Lines` item's ink keeps its width
        let mut factors = if rule.is_constant() || c.own.is_some() {
            vec![1.0; n]
        } else {
            rule.factors(&along, &depths, closed, reference)
        };
        if faded {
            factors.iter_mut().zip(&c.strength).for_each(|(f, &s)| *f *= strength_factor(s));
        }
        let ink = c.ink();
        let own = c.own.filter(|_| ink == LINES_KIND);
        let flags = if c.occlusion.is_some() { EXACT } else { 0 }
            | if c.own.is_some() { IN_VIEW } else { 0 }
            | if own.is_some() { OWN_INK } else { 0 };
        // the ink table has no row for a `Lines` item's own ink
        let kind = if own.is_some() { HIDDEN_KIND } else { ink };
        out.extend((1..n).map(|i| {
            let scale = [factors[i - 1] as f32, factors[i] as f32];
            let line =
                LineInstance { flags, ..LineInstance::of_ink(kind, c.points[i - 1], c.points[i], scale) };
            FrameLine { line, along: [along[i - 1] as f32, along[i] as f32], ink: own.unwrap_or_default() }
        }));
    }
    out
}

/// The depth (normalised view units) of the centre of the box around every item's bounding
/// sphere: where lines drawn with width by depth keep their width.
pub fn reference_depth(items: &[SceneItem], records: &[Arc<MeshRecord>], cam: &ResolvedCamera) -> f64 {
    let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for (item, rec) in items.iter().zip(records) {
        let sphere = rec.gpu.sphere();
        let m = item.model_matrix();
        let c = m.transform_point3(sphere.center);
        // the transform's largest stretch bounds the sphere's radius in the world
        let stretch = largest_stretch(&m);
        lo = lo.min(c - sphere.radius * stretch);
        hi = hi.max(c + sphere.radius * stretch);
    }
    let centre = (lo + hi) * 0.5;
    -(cam.normalized_view().transform_point3(centre)).z
}

/// The most the affine `m` lengthens a vector, bounded by its longest column.
pub fn largest_stretch(m: &DMat4) -> f64 {
    [m.x_axis, m.y_axis, m.z_axis].iter().map(|a| a.truncate().length()).fold(0.0, f64::max)
}

/// Every item's lines of the view of `cam`, with the borders between items resolved
/// (`shared_borders`).
pub fn scene_outlines(
    items: &[SceneItem],
    records: &[Arc<MeshRecord>],
    cam: &ResolvedCamera,
    o: &Outlines,
    sequence: Option<&SequenceFrame>,
) -> Result<Vec<MeshOutline>> {
    let mut outlines = Vec::with_capacity(items.len());
    let mut drawn = sequence.map(|s| s.drawn.lock().unwrap_or_else(|e| e.into_inner()));
    for (i, (item, rec)) in items.iter().zip(records).enumerate() {
        if item.splats {
            // a splat's edges are no lines of the surface: image-space edges ink the cloud
            outlines.push(MeshOutline { edges: Outline::default(), curves: Vec::new() });
            continue;
        }
        let stored = |cam: &ResolvedCamera| stored_view(cam, item.model_matrix(), &rec.gpu);
        let flat = rec.gpu.normals == NormalMode::Flat;
        let in_sequence = match (sequence, drawn.as_mut()) {
            (Some(s), Some(d)) => {
                Some((s.before.as_ref().map(stored), s.after.as_ref().map(stored), &mut d[i]))
            }
            _ => None,
        };
        outlines.push(MeshLines::of(rec).outline(&rec.host, flat, stored(cam), o, in_sequence)?);
    }
    if items.len() > 1 {
        let mut edges: Vec<&mut Outline> = outlines.iter_mut().map(|out| &mut out.edges).collect();
        shared_borders(items, records, cam, o, &mut edges, |i, edge| {
            let (host, lines) = (&records[i].host, MeshLines::of(&records[i]));
            let face = lines.index(host, o.weld).ok()?.faces_on(edge).next()?;
            // a face walks its edge from the smaller index to the larger unless reversed
            Some((lines.faces(host, o.weld)[face.face as usize], (edge[0] < edge[1]) != face.reversed))
        })?;
    }
    if o.styles[LineKind::Boundary as usize].is_none() {
        for out in &mut outlines {
            out.edges = out.edges.without(LineKind::Boundary);
        }
    }
    Ok(outlines)
}
