//! The render plan: from what a scene has (outline requests) and what the frame asks for
//! (outputs, MSAA, supersampling) to the passes that must run, and nothing else. The plan is
//! data: `names()` is what `RenderResult.passes` reports and what the tests hold.
//!
//! - `shadow_map` (depth from the shadow-casting light) runs when a light casts shadows and
//!   colour or the shadow output is asked for;
//! - `shade` runs when colour is asked for; at the output size with one sample per pixel it
//!   also writes the geometry target when the frame needs it;
//! - `gbuffer` writes the geometry target (normal and/or linear depth) when the frame needs it
//!   and `shade` cannot: the normal output or image-space edges need normals; the depth output,
//!   mesh-space lines and the visible-line polylines need depth;
//! - `downsample` averages supersampled colour;
//! - `shadow` (the light's visibility at each pixel) runs when the shadow output is asked for;
//! - `edges` (image-space outlines) and `lines` (mesh-space outlines) run when the scene asks
//!   for outlines and there is something to draw them into (colour or the outline output);
//! - one readback per target whose contents are asked for;
//! - on the host: `silhouettes` (the per-view half of mesh-space outlines) before the frame,
//!   `visible_lines` (the visible lines as polylines) after it.

use crate::render::graph::resources::ResourceKey;
use crate::render::graph::target::{GeometryLayout, Shape, Target};
use crate::render::graph::Pass;
use crate::render::passes::downsample::Downsample;
use crate::render::passes::edges::Edges;
use crate::render::passes::geometry::Geometry;
use crate::render::passes::lines::Lines;
use crate::render::passes::readback::{Readback, Region};
use crate::render::passes::shade::Shade;
use crate::render::passes::shadow::ShadowMask;
use crate::render::passes::shadow_map::ShadowMap;
use crate::render::scene::light::shadow_caster;
use crate::render::scene::{FrameSpec, Scene};

/// The scene's effects the plan depends on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Features {
    pub mesh_lines: bool,
    pub image_edges: bool,
    /// The shadow map's side, when a light casts shadows onto something.
    pub shadow_size: Option<u32>,
}

impl Features {
    pub fn of(scene: &Scene) -> Self {
        let caster = shadow_caster(&scene.lights).filter(|_| !scene.items.is_empty());
        Features {
            mesh_lines: scene.mesh_lines(),
            image_edges: scene.image_edges(),
            shadow_size: caster.map(|(_, _, s)| s.size),
        }
    }
}

/// The host step that finds each view's silhouettes.
pub const SILHOUETTES: &str = "silhouettes";
/// The host step that turns visible mesh-space lines into polylines.
pub const VISIBLE_LINES: &str = "visible_lines";

#[derive(Debug)]
pub struct Plan {
    pub passes: Vec<Box<dyn Pass>>,
    pub shape: Shape,
    /// Where each read-back target lies in the staging buffer.
    pub color: Option<Region>,
    pub geometry: Option<Region>,
    pub outline: Option<Region>,
    pub shadow: Option<Region>,
    /// Bytes of the readbacks (timestamps go after them).
    pub readback_bytes: u64,
    pub silhouettes: bool,
    pub visible_lines: bool,
}

/// The passes for `frame` of a scene with `features`, in the order they run.
pub fn plan(features: Features, frame: &FrameSpec) -> Plan {
    let o = frame.outputs;
    let ink = o.color || o.outline;
    let image = features.image_edges && ink;
    let lines = features.mesh_lines && ink;
    let visible_lines = features.mesh_lines && o.lines;
    let shadow_size = features.shadow_size.filter(|_| o.color || o.shadow);
    let shadow_output = o.shadow && shadow_size.is_some();
    let geometry = if o.normal || image || shadow_output {
        Some(GeometryLayout::NormalDepth)
    } else if o.depth || lines || visible_lines {
        Some(GeometryLayout::Depth)
    } else {
        None
    };
    let single = frame.msaa == 1 && frame.supersample == 1;
    let in_shade = o.color && single && geometry.is_some();
    let shape = Shape {
        width: frame.width,
        height: frame.height,
        msaa: frame.msaa,
        supersample: frame.supersample,
        geometry,
        shadow_size,
    };
    let mut passes: Vec<Box<dyn Pass>> = Vec::new();
    if shadow_size.is_some() {
        passes.push(Box::new(ShadowMap));
    }
    if o.color {
        passes.push(Box::new(Shade {
            samples: frame.msaa,
            supersampled: frame.supersample > 1,
            geometry: geometry.filter(|_| in_shade),
            shadowed: shadow_size.is_some(),
        }));
    }
    if let Some(layout) = geometry.filter(|_| !in_shade) {
        passes.push(Box::new(Geometry { layout }));
    }
    if o.color && frame.supersample > 1 {
        passes.push(Box::new(Downsample { factor: frame.supersample }));
    }
    if shadow_output {
        passes.push(Box::new(ShadowMask));
    }
    let mut clear_outline = o.outline;
    if image {
        passes.push(Box::new(Edges { color: o.color, outline: o.outline, clear_outline }));
        clear_outline = false;
    }
    if lines {
        let layout = geometry.expect("lines need depth");
        passes.push(Box::new(Lines { color: o.color, outline: o.outline, clear_outline, layout }));
    }
    let (w, h) = (frame.width, frame.height);
    let mut end = 0u64;
    let mut region = |bytes_per_pixel: u32| {
        let r = Region::at(end, w, h, bytes_per_pixel);
        end = r.end();
        r
    };
    let mut readback = |name: &'static str, target: Target, r: Region| {
        passes.push(Box::new(Readback { name, target, region: r }));
        Some(r)
    };
    let color = if o.color { readback("readback_color", Target::Color, region(4)) } else { None };
    let geometry_name = match (o.normal, o.depth || visible_lines) {
        (true, true) => Some("readback_normal_depth"),
        (true, false) => Some("readback_normal"),
        (false, true) => Some("readback_depth"),
        (false, false) => None,
    };
    let geometry_region = match (geometry_name, geometry) {
        (Some(name), Some(layout)) => {
            readback(name, Target::Geometry, region(4 * layout.words_per_pixel() as u32))
        }
        _ => None,
    };
    let outline = if o.outline { readback("readback_outline", Target::Outline, region(1)) } else { None };
    let shadow = if shadow_output { readback("readback_shadow", Target::Shadow, region(4)) } else { None };
    Plan {
        passes,
        shape,
        color,
        geometry: geometry_region,
        outline,
        shadow,
        readback_bytes: end,
        silhouettes: features.mesh_lines && (lines || visible_lines),
        visible_lines,
    }
}

impl Plan {
    /// Every step in order: host steps and passes.
    pub fn names(&self) -> Vec<&'static str> {
        let mut names = Vec::with_capacity(self.passes.len() + 2);
        if self.silhouettes {
            names.push(SILHOUETTES);
        }
        names.extend(self.passes.iter().map(|p| p.name()));
        if self.visible_lines {
            names.push(VISIBLE_LINES);
        }
        names
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
        ResourceKey {
            textures: usage.into_iter().map(|(t, u)| (t, t.desc(&self.shape), u)).collect(),
            staging_bytes,
            queries,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::scene::Outputs;

    fn names(features: Features, f: &FrameSpec) -> Vec<&'static str> {
        plan(features, f).names()
    }

    const NONE: Features = Features { mesh_lines: false, image_edges: false, shadow_size: None };

    #[test]
    fn minimal_scene_runs_one_pass_and_one_readback() {
        assert_eq!(names(NONE, &FrameSpec::default()), ["shade", "readback_color"]);
    }

    #[test]
    fn geometry_joins_shading_only_when_sample_counts_match() {
        let mut f = FrameSpec {
            outputs: Outputs { color: true, normal: true, depth: true, ..Default::default() },
            ..Default::default()
        };
        assert_eq!(names(NONE, &f), ["shade", "readback_color", "readback_normal_depth"]);
        f.msaa = 4;
        f.supersample = 2;
        assert_eq!(
            names(NONE, &f),
            ["shade", "gbuffer", "downsample", "readback_color", "readback_normal_depth"]
        );
        f.outputs = Outputs { depth: true, ..Default::default() };
        assert_eq!(names(NONE, &f), ["gbuffer", "readback_depth"]);
        assert_eq!(plan(NONE, &f).shape.geometry, Some(GeometryLayout::Depth));
    }

    #[test]
    fn outlines_run_only_when_asked_for_and_drawable() {
        let both = Features { mesh_lines: true, image_edges: true, shadow_size: None };
        let f = FrameSpec::default();
        assert_eq!(names(both, &f), ["silhouettes", "shade", "edges", "lines", "readback_color"]);
        // image edges need normals, produced but not read back
        let p = plan(Features { mesh_lines: false, image_edges: true, shadow_size: None }, &f);
        assert_eq!(p.shape.geometry, Some(GeometryLayout::NormalDepth));
        assert!(p.geometry.is_none());
        // nothing to draw ink into: no ink pass
        let depth_only = FrameSpec { outputs: Outputs { depth: true, ..Default::default() }, ..f };
        assert_eq!(names(both, &depth_only), ["gbuffer", "readback_depth"]);
        // the outline output alone
        let outline = FrameSpec { outputs: Outputs { outline: true, ..Default::default() }, ..f };
        assert_eq!(names(both, &outline), ["silhouettes", "gbuffer", "edges", "lines", "readback_outline"]);
        // vector lines read depth back without returning it
        let lines = FrameSpec { outputs: Outputs { color: true, lines: true, ..Default::default() }, ..f };
        assert_eq!(
            names(Features { mesh_lines: true, image_edges: false, shadow_size: None }, &lines),
            ["silhouettes", "shade", "lines", "readback_color", "readback_depth", "visible_lines"]
        );
    }

    #[test]
    fn shadows_run_only_when_a_light_casts_them_and_something_uses_them() {
        let lit = Features { shadow_size: Some(1024), ..NONE };
        let f = FrameSpec::default();
        assert_eq!(names(lit, &f), ["shadow_map", "shade", "readback_color"]);
        // the shadow output alone: no shading, the visibility from the normals and depths
        let mask = FrameSpec { outputs: Outputs { shadow: true, ..Default::default() }, ..f };
        assert_eq!(names(lit, &mask), ["shadow_map", "gbuffer", "shadow", "readback_shadow"]);
        assert_eq!(plan(lit, &mask).shape.geometry, Some(GeometryLayout::NormalDepth));
        let both = FrameSpec { outputs: Outputs { color: true, shadow: true, ..Default::default() }, ..f };
        assert_eq!(names(lit, &both), ["shadow_map", "shade", "shadow", "readback_color", "readback_shadow"]);
        // nothing lit is asked for: no shadow map
        let depth = FrameSpec { outputs: Outputs { depth: true, ..Default::default() }, ..f };
        assert_eq!(names(lit, &depth), ["gbuffer", "readback_depth"]);
        let key = plan(lit, &f).resource_key(false);
        let map = key.textures.iter().find(|x| x.0 == Target::ShadowMap).expect("a shadow map");
        assert_eq!(map.1.size, (1024, 1024));
    }

    #[test]
    fn targets_get_the_usages_their_passes_declare() {
        let f = FrameSpec { supersample: 2, ..Default::default() };
        let key =
            plan(Features { mesh_lines: true, image_edges: false, shadow_size: None }, &f).resource_key(true);
        let usage = |t| key.textures.iter().find(|x| x.0 == t).map(|x| x.2);
        use wgpu::TextureUsages as U;
        assert_eq!(usage(Target::ColorHi), Some(U::RENDER_ATTACHMENT | U::TEXTURE_BINDING));
        assert_eq!(usage(Target::Color), Some(U::RENDER_ATTACHMENT | U::COPY_SRC));
        assert_eq!(usage(Target::Geometry), Some(U::RENDER_ATTACHMENT | U::TEXTURE_BINDING));
        assert_eq!(usage(Target::ColorMs), None);
        assert_eq!(key.queries, 2 * 4);
    }
}
