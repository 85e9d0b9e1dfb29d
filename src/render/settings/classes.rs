//! Every settings class, listed once: its name (which front ends give it too), where its docs are (below `src/render`), its core type, and its
//! constructors (`new` for `Class(...)`, then `fn name` for each `Class.name(...)`, whose
//! docstring is `<docs>/Class.name.md`). `Setting` (a settings value held by another's field),
//! each type's `Class` (its name and its docstring, `<docs>/Class.md`), the Python classes and
//! the stub's list of classes are written from this list, so a new settings class is one line
//! here and its `Described` impl.

/// Calls `$then! { Class("docs") = path::Type { constructors } ... }` with the list.
macro_rules! settings_classes {
    ($then:ident) => {
        $then! {
            Dither("settings/docs") = $crate::render::effects::dither::Dither { new; }
            Rim("effects/rim/docs") = $crate::render::effects::rim::Rim { new; }
            Shadows("settings/docs") = $crate::render::effects::shadows::settings::Shadows { new; }
            Light("settings/docs") = $crate::render::scene::light::Light {
                fn directional; fn point; fn key;
            }
            Camera("settings/docs") = $crate::render::scene::camera::Camera {
                fn fit; fn look_at; fn orthographic;
            }
            LineStyle("settings/docs") = $crate::render::effects::outlines::settings::LineStyle { new; }
            Outlines("settings/docs") = $crate::render::effects::outlines::settings::Outlines { new; }
            Material("settings/docs") = $crate::render::scene::material::Material {
                fn lambert; fn phong; fn thresholded_phong; fn bands; fn hatching; fn lut;
            }
            Paper("effects/paper/docs") = $crate::render::effects::paper::settings::Paper { new; }
            EyeDome("effects/eye_dome/docs") = $crate::render::effects::eye_dome::settings::EyeDome { new; }
            RenderOptions("settings/docs") = $crate::render::scene::options::RenderOptions { new; }
        }
    };
}
pub(crate) use settings_classes;

/// `Setting`: one variant per class.
macro_rules! setting_enum {
    ($($class:ident($docs:literal) = $core:path { $($ctors:tt)* })*) => {
        /// A settings value held by another's field (boxed in `Value`, so its size is paid once).
        #[derive(Clone, Debug, PartialEq)]
        #[allow(clippy::large_enum_variant)]
        pub enum Setting {
            $($class($core),)*
        }

        /// Every settings class's name, in the list's order.
        pub const CLASSES: &[&str] = &[$(stringify!($class)),*];
    };
}

settings_classes!(setting_enum);

/// A settings type's class: its name and its docstring.
pub trait Class {
    const CLASS: &'static str;
    const HELP: &'static str;
}

/// `Class` for each type of the list.
macro_rules! class_impls {
    ($($class:ident($docs:literal) = $core:path { $($ctors:tt)* })*) => {
        $(impl Class for $core {
            const CLASS: &'static str = stringify!($class);
            const HELP: &'static str = include_str!(concat!(
                env!("CARGO_MANIFEST_DIR"), "/src/render/", $docs, "/", stringify!($class), ".md"
            ));
        })*
    };
}

settings_classes!(class_impls);

/// `Setting::at_pixel_ratio`: each class's value through `super::at_pixel_ratio`.
macro_rules! setting_at_pixel_ratio {
    ($($class:ident($docs:literal) = $core:path { $($ctors:tt)* })*) => {
        impl Setting {
            /// The value with its lengths in output pixels multiplied by `ratio`.
            pub fn at_pixel_ratio(self, ratio: f64) -> Setting {
                match self {
                    $(Setting::$class(v) => Setting::$class(super::at_pixel_ratio(&v, ratio)),)*
                }
            }
        }
    };
}

settings_classes!(setting_at_pixel_ratio);

/// `FieldValue` for each class: a field that holds a settings value. True is the class's
/// default and False none (a light's `shadows=True`); another form is the class's `shorthand`.
macro_rules! setting_field_values {
    ($($class:ident($docs:literal) = $core:path { $($ctors:tt)* })*) => {$(
        impl super::FieldValue for $core {
            fn to_value(&self) -> super::Value {
                super::Value::setting(Setting::$class(self.clone()))
            }

            fn from_value(field: &str, value: super::Value) -> crate::error::Result<Self> {
                match value {
                    super::Value::Setting(s) => match *s {
                        Setting::$class(v) => Ok(v),
                        other => Err(super::mismatch(field, &super::Value::setting(other))),
                    },
                    super::Value::Bool(true) => Ok(Self::default()),
                    other => <$core as super::Described>::shorthand(field, other),
                }
            }

            fn from_optional(field: &str, value: super::Value) -> crate::error::Result<Option<Self>> {
                match value {
                    super::Value::None | super::Value::Bool(false) => Ok(None),
                    other => Self::from_value(field, other).map(Some),
                }
            }
        }
    )*};
}

settings_classes!(setting_field_values);
