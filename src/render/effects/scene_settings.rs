//! The settings a scene carries for frame effects that are not tied to a light or a material
//! (paper grain), listed once: each is a field of `Scene` and of `RenderOptions` (a render
//! keyword of the same name, described from this list), checked with the scene.

use serde::{Deserialize, Serialize};

use crate::error::Result;
use crate::render::settings::declare::declared_fields;
use crate::render::settings::Kind;

/// Writes `SceneEffects` and its fields' declaration from the list: each effect's field (its render
/// keyword), its settings type, that type's name among the settings classes, and the keyword's
/// one line of help.
macro_rules! scene_effects {
    ($($name:ident: $class:ident = $settings:ty, $help:literal,)*) => {
        /// The frame effects' settings a scene carries (None: the effect is not used).
        #[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
        #[serde(default)]
        pub struct SceneEffects {
            $(pub $name: Option<$settings>,)*
        }

        // (an empty list leaves the arguments unused)
        #[allow(unused_variables)]
        impl SceneEffects {
            /// Checks each, naming it as its render keyword.
            pub fn validate(&self) -> Result<()> {
                $(if let Some(s) = &self.$name {
                    s.validate(stringify!($name))?;
                })*
                Ok(())
            }

            /// Each with its lengths in output pixels multiplied by `ratio`.
            pub fn at_pixel_ratio(&self, ratio: f64) -> SceneEffects {
                SceneEffects {
                    $($name: self.$name.as_ref().map(|s| crate::render::settings::at_pixel_ratio(s, ratio)),)*
                }
            }
        }

        // each a field of `RenderOptions` (`..effects`): None or the effect's settings
        declared_fields! {
            SceneEffects {
                $($name: Option<$settings> [.$name] => Kind::Setting(stringify!($class)), $help, optional;)*
            }
        }
    };
}

scene_effects! {
    paper: Paper = super::paper::settings::Paper, "paper grain over the image: None or a Paper",
    eye_dome: EyeDome = super::eye_dome::settings::EyeDome,
        "eye-dome lighting (surfaces darkened where they lie behind their neighbours, as point-cloud viewers draw): None or an EyeDome",
}
