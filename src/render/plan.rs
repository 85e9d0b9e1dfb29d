//! The render plan: from what a checked scene has and what its frame asks for (outputs, MSAA,
//! supersampling) to the passes and host steps that must run, and nothing else. The plan is
//! data: `names()` is what `RenderResult.passes` reports and what the tests hold.
//!
//! The core's part:
//! - `shade` runs when colour is asked for; at the output size with one sample per pixel it
//!   also writes the geometry target when the frame needs it;
//! - `gbuffer` writes the geometry target (normal and/or linear depth) when the frame needs it
//!   and `shade` cannot: the normal and depth outputs need it, and so may frame effects;
//! - `downsample` averages supersampled colour;
//! - one readback per target whose contents are asked for.
//!
//! Each frame effect (`effects::frame::FRAME`) adds its own: passes before shading (a shadow
//! map), after it (a shadow mask, ink), readbacks, and host steps before the frame
//! (`silhouettes`) or after it (`visible_lines`).

use crate::render::effects::frame::{frame_members, FRAME};
use crate::render::graph::effect::{HostStep, PlanInputs, Steps};
use crate::render::graph::resources::ResourceKey;
use crate::render::graph::target::{GeometryLayout, Shape, Target};
use crate::render::graph::Pass;
use crate::render::passes::downsample::Downsample;
use crate::render::passes::geometry::Geometry;
use crate::render::passes::glass;
use crate::render::passes::readback::{Readback, Region};
use crate::render::passes::shade::Shade;
use crate::render::scene::checked::CheckedScene;
use crate::render::scene::Output;
use crate::render::uniforms::draw_members;

/// How a read-back region is copied out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Copy {
    /// Bytes as they are (colour).
    Bytes,
    /// f32 words `first..first + keep` of each pixel; depths scaled to world units when `world`.
    Words { first: usize, keep: usize, world: bool },
    /// Unsigned normalised bytes to f32 in [0, 1] (coverage).
    Unorm8,
}

/// Where a copy goes: an output, or the depth the host steps after the frame read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dest {
    Output(Output),
    HostDepth,
}

/// A region of the staging buffer and what is copied out of it.
#[derive(Clone, Debug, PartialEq)]
pub struct ReadPlan {
    pub region: Region,
    pub copies: Vec<(Dest, Copy)>,
}

#[derive(Debug)]
pub struct Plan {
    pub passes: Vec<Box<dyn Pass>>,
    pub shape: Shape,
    pub reads: Vec<ReadPlan>,
    /// Bytes of the readbacks (timestamps go after them).
    pub readback_bytes: u64,
    pub host_before: Vec<Box<dyn HostStep>>,
    pub host_after: Vec<Box<dyn HostStep>>,
}

/// The wider of two geometry layouts (normal and depth holds depth too).
fn wider(a: Option<GeometryLayout>, b: Option<GeometryLayout>) -> Option<GeometryLayout> {
    match (a, b) {
        (Some(GeometryLayout::NormalDepth), _) | (_, Some(GeometryLayout::NormalDepth)) => {
            Some(GeometryLayout::NormalDepth)
        }
        (x, y) => x.or(y),
    }
}

/// How a target an effect reads back is laid out and copied.
fn copy_of(target: Target) -> (u32, Copy) {
    match target {
        Target::Outline => (1, Copy::Unorm8),
        Target::Shadow => (4, Copy::Words { first: 0, keep: 1, world: false }),
        _ => (4, Copy::Bytes),
    }
}

/// The passes and steps for `scene`'s frame, in the order they run.
pub fn plan(scene: &CheckedScene) -> Plan {
    let frame = &scene.frame;
    let o = frame.outputs;
    let mut geometry = if o.has(Output::Normal) {
        Some(GeometryLayout::NormalDepth)
    } else if o.has(Output::Depth) {
        Some(GeometryLayout::Depth)
    } else {
        None
    };
    for e in FRAME {
        geometry = wider(geometry, e.geometry(scene));
    }
    // glass is peeled against the opaque surfaces' depth
    let glass = scene.has_glass();
    if glass {
        geometry = wider(geometry, Some(GeometryLayout::Depth));
    }
    let color = o.has(Output::Color);
    let single = frame.msaa == 1 && frame.supersample == 1;
    let in_shade = color && single && geometry.is_some();
    let mut steps = Steps {
        shape: Shape {
            width: frame.width,
            height: frame.height,
            msaa: frame.msaa,
            supersample: frame.supersample,
            geometry,
            shadow_size: None,
        },
        ..Default::default()
    };
    let cx = PlanInputs { scene, geometry };
    let mut glass_at = None;
    for e in FRAME {
        if e.over_glass() && glass_at.is_none() {
            glass_at = Some(steps.after.len());
        }
        e.plan(&cx, &mut steps);
    }
    if glass {
        let at = glass_at.unwrap_or(steps.after.len());
        let mut passes = glass::passes(frame.glass_layers);
        passes.append(&mut steps.over_glass);
        steps.after.splice(at..at, passes);
    }
    let mut passes = std::mem::take(&mut steps.before);
    if color {
        passes.push(Box::new(Shade {
            samples: frame.msaa,
            supersampled: frame.supersample > 1,
            geometry: geometry.filter(|_| in_shade),
            hook: steps.shade_hook.clone(),
        }));
    }
    if let Some(layout) = geometry.filter(|_| !in_shade) {
        passes.push(Box::new(Geometry { layout }));
    }
    if color && frame.supersample > 1 {
        passes.push(Box::new(Downsample { factor: frame.supersample }));
    }
    passes.append(&mut steps.after);

    // readbacks, in the order of the outputs
    let (w, h) = (frame.width, frame.height);
    let mut end = 0u64;
    let mut reads = Vec::new();
    let mut read_back = |passes: &mut Vec<Box<dyn Pass>>, name, target, bytes_per_pixel, copies| {
        let region = Region::at(end, w, h, bytes_per_pixel);
        end = region.end();
        passes.push(Box::new(Readback { name, target, region }) as Box<dyn Pass>);
        reads.push(ReadPlan { region, copies });
    };
    if color {
        read_back(
            &mut passes,
            "readback_color",
            Target::Color,
            4,
            vec![(Dest::Output(Output::Color), Copy::Bytes)],
        );
    }
    if let Some(layout) = geometry {
        let depth = layout.depth_component();
        let mut copies = Vec::new();
        if o.has(Output::Normal) {
            copies.push((Dest::Output(Output::Normal), Copy::Words { first: 0, keep: 3, world: false }));
        }
        if o.has(Output::Depth) {
            copies.push((Dest::Output(Output::Depth), Copy::Words { first: depth, keep: 1, world: true }));
        }
        if steps.host_depth {
            copies.push((Dest::HostDepth, Copy::Words { first: depth, keep: 1, world: false }));
        }
        let name = match (o.has(Output::Normal), o.has(Output::Depth) || steps.host_depth) {
            (true, true) => Some("readback_normal_depth"),
            (true, false) => Some("readback_normal"),
            (false, true) => Some("readback_depth"),
            (false, false) => None,
        };
        if let Some(name) = name {
            read_back(&mut passes, name, Target::Geometry, 4 * layout.words_per_pixel() as u32, copies);
        }
    }
    steps.readbacks.sort_by_key(|r| r.output);
    for r in &steps.readbacks {
        let (bytes, copy) = copy_of(r.target);
        read_back(&mut passes, r.name, r.target, bytes, vec![(Dest::Output(r.output), copy)]);
    }
    Plan {
        passes,
        shape: steps.shape,
        reads,
        readback_bytes: end,
        host_before: steps.host_before,
        host_after: steps.host_after,
    }
}

impl Plan {
    /// Every step in order: host steps and passes.
    pub fn names(&self) -> Vec<&'static str> {
        let before = self.host_before.iter().map(|s| s.name());
        let passes = self.passes.iter().map(|p| p.name());
        before.chain(passes).chain(self.host_after.iter().map(|s| s.name())).collect()
    }

    /// Passes timed on the GPU.
    pub fn timed(&self) -> usize {
        self.passes.iter().filter(|p| p.timed()).count()
    }

    /// Where the timestamps go in the staging buffer (8 bytes each, two per timed pass).
    pub fn timestamp_offset(&self) -> u64 {
        self.readback_bytes.div_ceil(256) * 256
    }

    /// The resources this plan needs: each target its passes declare, with the union of the
    /// usages they declare.
    pub fn resource_key(&self, timestamps: bool) -> ResourceKey {
        let mut usage = std::collections::BTreeMap::<Target, wgpu::TextureUsages>::new();
        for u in self.passes.iter().flat_map(|p| p.uses()) {
            *usage.entry(u.0).or_insert(wgpu::TextureUsages::empty()) |= u.1.usage();
        }
        let queries = if timestamps { 2 * self.timed() as u32 } else { 0 };
        let staging_bytes =
            if queries > 0 { self.timestamp_offset() + 8 * queries as u64 } else { self.readback_bytes };
        let bytes = |members: crate::render::uniforms::Members| members.iter().map(|m| m.1.size as u64).sum();
        ResourceKey {
            textures: usage.into_iter().map(|(t, u)| (t, t.desc(&self.shape), u)).collect(),
            staging_bytes,
            queries,
            uniform_bytes: (bytes(frame_members()), bytes(draw_members())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::effects::outlines::settings::Outlines;
    use crate::render::effects::shadows::settings::Shadows;
    use crate::render::scene::checked::DeviceLimits;
    use crate::render::scene::light::Light;
    use crate::render::scene::{FrameSpec, Outputs, Scene, SceneItem, IDENTITY};

    /// A scene of one (unresolved) mesh with the given outlines and a shadow-casting light or not.
    fn scene(outlines: Option<Outlines>, shadows: bool) -> Scene {
        let light = Light {
            shadows: shadows.then(|| Shadows { size: 1024, ..Default::default() }),
            ..Light::default()
        };
        Scene {
            items: vec![SceneItem {
                mesh: 1,
                transform: IDENTITY,
                material: Default::default(),
                splats: false,
            }],
            lights: vec![if shadows {
                Light {
                    kind: crate::render::scene::light::LightKind::Directional { direction: [0.0, -1.0, 0.0] },
                    ..light
                }
            } else {
                light
            }],
            outlines,
            ..Default::default()
        }
    }

    fn checked(scene: Scene, frame: FrameSpec) -> CheckedScene {
        let limits = DeviceLimits { max_texture_size: 8192, msaa_samples: vec![1, 4] };
        CheckedScene::check(scene, frame, &limits).unwrap()
    }

    fn names(scene: Scene, frame: FrameSpec) -> Vec<&'static str> {
        plan(&checked(scene, frame)).names()
    }

    fn outputs(o: &[Output]) -> FrameSpec {
        FrameSpec { outputs: Outputs::of(o), ..Default::default() }
    }

    #[test]
    fn minimal_scene_runs_one_pass_and_one_readback() {
        assert_eq!(names(scene(None, false), FrameSpec::default()), ["shade", "readback_color"]);
    }

    #[test]
    fn geometry_joins_shading_only_when_sample_counts_match() {
        let mut f = outputs(&[Output::Color, Output::Normal, Output::Depth]);
        assert_eq!(names(scene(None, false), f), ["shade", "readback_color", "readback_normal_depth"]);
        f.msaa = 4;
        f.supersample = 2;
        assert_eq!(
            names(scene(None, false), f),
            ["shade", "gbuffer", "downsample", "readback_color", "readback_normal_depth"]
        );
        f.outputs = Outputs::of(&[Output::Depth]);
        assert_eq!(names(scene(None, false), f), ["gbuffer", "readback_depth"]);
        assert_eq!(plan(&checked(scene(None, false), f)).shape.geometry, Some(GeometryLayout::Depth));
    }

    #[test]
    fn outlines_run_only_when_asked_for_and_drawable() {
        let both = || scene(Some(Outlines::new(true, true)), false);
        let f = FrameSpec::default();
        assert_eq!(
            names(both(), f),
            ["silhouettes", "shade", "edge_bits", "edges", "lines", "readback_color"]
        );
        // image edges need normals, produced but not read back
        let p = plan(&checked(scene(Some(Outlines::new(false, true)), false), f));
        assert_eq!(p.shape.geometry, Some(GeometryLayout::NormalDepth));
        assert_eq!(p.reads.len(), 1);
        // nothing to draw ink into: no ink pass
        assert_eq!(names(both(), outputs(&[Output::Depth])), ["gbuffer", "readback_depth"]);
        // the outline output alone
        assert_eq!(
            names(both(), outputs(&[Output::Outline])),
            ["silhouettes", "gbuffer", "edge_bits", "edges", "lines", "readback_outline"]
        );
        // vector lines cut by the exact rule need no depth; by the depth rule they read it
        // back without returning it
        let lines = outputs(&[Output::Color, Output::Lines]);
        assert_eq!(
            names(scene(Some(Outlines::new(true, false)), false), lines),
            ["silhouettes", "shade", "lines", "readback_color", "visible_lines"]
        );
        let by_depth = Outlines {
            visibility: crate::render::effects::outlines::settings::VisibilityRule::Depth,
            ..Outlines::new(true, false)
        };
        assert_eq!(
            names(scene(Some(by_depth), false), lines),
            ["silhouettes", "shade", "lines", "readback_color", "readback_depth", "visible_lines"]
        );
        // outlines that draw nothing still give an empty coverage
        let mut none = Outlines::new(true, false);
        none.styles = [None; crate::render::effects::outlines::settings::INK_KINDS];
        assert_eq!(
            names(scene(Some(none), false), outputs(&[Output::Outline])),
            ["clear_outline", "readback_outline"]
        );
    }

    #[test]
    fn shadows_run_only_when_a_light_casts_them_and_something_uses_them() {
        let lit = || scene(None, true);
        let f = FrameSpec::default();
        assert_eq!(names(lit(), f), ["shadow_map", "shade", "readback_color"]);
        // the shadow output alone: no shading, the visibility from the normals and depths
        let mask = outputs(&[Output::Shadow]);
        assert_eq!(names(lit(), mask), ["shadow_map", "gbuffer", "shadow", "readback_shadow"]);
        assert_eq!(plan(&checked(lit(), mask)).shape.geometry, Some(GeometryLayout::NormalDepth));
        assert_eq!(
            names(lit(), outputs(&[Output::Color, Output::Shadow])),
            ["shadow_map", "shade", "shadow", "readback_color", "readback_shadow"]
        );
        // nothing lit is asked for: no shadow map
        assert_eq!(names(lit(), outputs(&[Output::Depth])), ["gbuffer", "readback_depth"]);
        // an empty scene: nothing to shade with shadows, but the shadow output is all lit
        let empty = Scene { items: vec![], ..lit() };
        assert_eq!(names(empty.clone(), f), ["shade", "readback_color"]);
        assert_eq!(names(empty, mask), ["shadow_map", "gbuffer", "shadow", "readback_shadow"]);
        let key = plan(&checked(lit(), f)).resource_key(false);
        let map = key.textures.iter().find(|x| x.0 == Target::ShadowMap).expect("a shadow map");
        assert_eq!(map.1.size, (1024, 1024));
    }

    #[test]
    fn glass_runs_its_passes_only_when_colour_is_asked_for() {
        let mut glass = scene(None, false);
        glass.items[0].material.opacity = 0.5;
        let f = FrameSpec { glass_layers: 2, ..Default::default() };
        let layers = ["glass_peel", "glass_under", "glass_peel", "glass_under"];
        let want: Vec<&str> =
            [&["shade", "glass_clear"][..], &layers, &["glass_composite", "readback_color"]].concat();
        assert_eq!(names(glass.clone(), f), want);
        // peeled against the opaque surfaces' depth, which the shading pass writes
        assert_eq!(plan(&checked(glass.clone(), f)).shape.geometry, Some(GeometryLayout::Depth));
        assert_eq!(names(glass, outputs(&[Output::Depth])), ["gbuffer", "readback_depth"]);
        assert_eq!(names(scene(None, false), f), ["shade", "readback_color"]);
        // the opaque items' ink under the glass, the glass's own over it
        let mut inked = scene(Some(Outlines::new(true, false)), false);
        inked.items[0].material.opacity = 0.5;
        let one = FrameSpec { glass_layers: 1, ..f };
        assert_eq!(
            names(inked, one),
            [
                "silhouettes",
                "shade",
                "lines",
                "glass_clear",
                "glass_peel",
                "glass_under",
                "glass_composite",
                "glass_lines",
                "readback_color"
            ]
        );
    }

    #[test]
    fn targets_get_the_usages_their_passes_declare() {
        let f = FrameSpec { supersample: 2, ..Default::default() };
        let key = plan(&checked(scene(Some(Outlines::new(true, false)), false), f)).resource_key(true);
        let usage = |t| key.textures.iter().find(|x| x.0 == t).map(|x| x.2);
        use wgpu::TextureUsages as U;
        assert_eq!(usage(Target::ColorHi), Some(U::RENDER_ATTACHMENT | U::TEXTURE_BINDING));
        assert_eq!(usage(Target::Color), Some(U::RENDER_ATTACHMENT | U::COPY_SRC));
        assert_eq!(usage(Target::Geometry), Some(U::RENDER_ATTACHMENT | U::TEXTURE_BINDING));
        assert_eq!(usage(Target::ColorMs), None);
        assert_eq!(key.queries, 2 * 4);
    }
}
