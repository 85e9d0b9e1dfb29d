//! The paper's settings, declared (`render::settings::declare`).

use crate::error::Result;
use crate::render::settings::{check_bounds, settings, GreyImage};

crate::named_enum! {
    /// What the grain is fixed to.
    pub enum PaperSpace {
        /// The image's pixels: the grain stays still while the scene moves under it.
        Screen = "screen",
        /// The scene's surfaces (world coordinates, mapped on the three axis planes): it turns
        /// with the view, as a painted object's paper would.
        Surface = "surface",
    }
}

settings! {
    #[derive(Clone, Debug, PartialEq)]
    pub struct Paper {
        /// The grain heights (None: the built-in procedural grain, `grain::procedural`), tiled.
        pub grain: Option<GreyImage> = None => image(),
            "the grain's heights: None (a built-in grain) or an image, (H, W) or (H, W, C), tiled", optional;
        pub space: PaperSpace = PaperSpace::Screen => choice(PaperSpace::NAMES),
            "what the grain is fixed to: the 'screen' or the scene's 'surface'";
        /// Output pixels a grain texel covers (on the surface: at the scene's centre).
        pub scale: f64 = 1.5 => float(closed(0.25, 64.0)), "output pixels a grain texel covers, 0.25 to 64", pixels;
        /// How much of the pigment the grain's valleys refuse: 0 none, 1 all.
        pub strength: f64 = 0.3 => float(closed(0.0, 1.0)), "how much pigment the grain's valleys refuse, 0 to 1";
        /// How much the blank paper's valleys darken it: 0 not at all.
        pub tone: f64 = 0.1 => float(closed(0.0, 1.0)), "how much the blank paper's valleys darken it, 0 to 1";
    }
    described(positional: 1);
}

impl Paper {
    /// Checks the settings; `prefix` names them in errors ("" while they are being made). Its
    /// numbers' bounds are its declaration's; the grain was checked when it was read.
    pub fn validate(&self, prefix: &str) -> Result<()> {
        check_bounds(self, prefix)
    }

    /// The linear colour `c` of a pixel whose grain height is `g`: the CPU reference of
    /// `paper_blend` in paper.wgsl with the pass's blending.
    pub fn color(&self, c: [f32; 3], g: f32) -> [f32; 3] {
        let m = 1.0 - self.strength as f32 * (1.0 - g);
        let paper = 1.0 - self.tone as f32 * (1.0 - g);
        c.map(|x| paper * (1.0 - m) + x * m)
    }
}
