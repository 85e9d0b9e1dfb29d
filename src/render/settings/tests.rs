//! Every settings type's description against its values: each constructor's arguments make
//! the value again, `replace` changes only what it names, and every field reads back what it set.

use super::*;
use crate::render::effects::dither::Dither;
use crate::render::effects::outlines::settings::{LineStyle, Outlines};
use crate::render::effects::shadows::settings::Shadows;
use crate::render::scene::camera::Camera;
use crate::render::scene::light::Light;
use crate::render::scene::material::Material;
use crate::render::scene::options::RenderOptions;

/// Each constructor's value with no arguments, and with every parameter changed from its
/// default where a second value is easy to name, makes itself again from its arguments.
fn round_trips<T: Described + std::fmt::Debug>() {
    for c in T::CONSTRUCTORS {
        let v = T::start(c.name);
        let (ctor, args) = arguments(&v);
        assert_eq!(ctor.name, c.name, "{}: made by another constructor", T::CLASS);
        let again: T = T::construct(c.name, args).unwrap_or_else(|e| panic!("{}.{}: {e}", T::CLASS, c.name));
        assert_eq!(again, v, "{}.{}", T::CLASS, c.name);
        for f in T::FIELDS {
            let got = v.get(f.name);
            if got != Value::None && !f.fixed {
                let mut w = v.clone();
                w.set(f.name, got.clone()).unwrap_or_else(|e| panic!("{}.{}: {e}", T::CLASS, f.name));
                assert_eq!(w, v, "{}.{} does not read back what it set", T::CLASS, f.name);
            }
        }
    }
}

#[test]
fn every_constructor_makes_its_value_again() {
    round_trips::<Material>();
    round_trips::<Dither>();
    round_trips::<Light>();
    round_trips::<Shadows>();
    round_trips::<Camera>();
    round_trips::<LineStyle>();
    round_trips::<Outlines>();
    round_trips::<RenderOptions>();
}

#[test]
fn a_base_colour_is_printed_as_the_coefficients_it_set() {
    let m: Material =
        Material::construct("lambert", vec![("color", Value::Triple([0.2, 0.4, 0.6]))]).unwrap();
    let (_, args) = arguments(&m);
    let names: Vec<&str> = args.iter().map(|(n, _)| *n).collect();
    assert_eq!(names, ["ambient", "diffuse"]);
    assert_eq!(Material::construct("lambert", args).unwrap(), m);
    let b: Material = Material::construct("bands", vec![("color", Value::Triple([0.2, 0.4, 0.6]))]).unwrap();
    assert_eq!(arguments(&b).1, vec![("color", Value::Triple([0.2, 0.4, 0.6]))]);
}

#[test]
fn a_field_the_constructor_does_not_take_is_replaced_after_the_call() {
    let b: Material = Material::construct("bands", vec![("color", Value::Triple([0.5; 3]))]).unwrap();
    let dark = replace(&b, vec![("ambient".into(), Some(Value::Triple([0.1; 3])))]).unwrap();
    let (ctor, args) = arguments(&dark);
    assert_eq!(replaced(&dark, ctor, &args), vec![("ambient", Value::Triple([0.1; 3]))]);
    let text = call(&dark, |v| Ok::<_, ()>(format!("{v:?}"))).unwrap();
    assert!(text.starts_with("Material.bands(") && text.contains(").replace(ambient="), "{text}");
    assert!(replaced(&b, ctor, &arguments(&b).1).is_empty());
}

#[test]
fn replace_changes_only_the_field_named_and_checks_it() {
    let o = Outlines::default();
    let r = replace(&o, vec![("crease_angle".into(), Some(Value::Float(45.0)))]).unwrap();
    assert_eq!(r.crease_angle, 45.0);
    assert_eq!(Outlines { crease_angle: o.crease_angle, ..r.clone() }, o);
    let e = replace(&o, vec![("crease_angle".into(), Some(Value::Float(200.0)))]).unwrap_err();
    assert!(e.to_string().starts_with("crease_angle"), "{e}");
    let e = replace(&o, vec![("crease_angel".into(), Some(Value::Float(20.0)))]).unwrap_err();
    assert!(e.to_string().contains("did you mean 'crease_angle'"), "{e}");
    let back = replace(&r, vec![("crease_angle".into(), None)]).unwrap();
    assert_eq!(back, o);
}

#[test]
fn the_common_style_reaches_every_kind_given_as_true() {
    let red = [1.0, 0.0, 0.0];
    let o = Outlines::construct(
        "",
        vec![
            ("color", Value::Triple(red)),
            ("suggestive", Value::Bool(true)),
            ("crease", Value::Bool(false)),
        ],
    )
    .unwrap();
    let style = |k: &str| o.get(k);
    let red_style = Value::setting(Setting::LineStyle(LineStyle { color: red, ..LineStyle::default() }));
    assert_eq!(style("silhouette"), red_style);
    assert_eq!(style("suggestive"), red_style);
    assert_eq!(style("ridge"), Value::Bool(false));
    let (_, args) = arguments(&o);
    assert_eq!(Outlines::construct("", args).unwrap(), o);
}

#[test]
fn unknown_and_missing_arguments_are_named() {
    let e = Light::construct("directional", vec![]).unwrap_err();
    assert!(e.to_string().starts_with("direction:"), "{e}");
    let e = check_arguments::<RenderOptions>(constructor::<RenderOptions>(""), &["widht"]).unwrap_err();
    assert!(e.to_string().starts_with("widht: not a render option; did you mean 'width'"), "{e}");
}

#[test]
fn a_pixel_ratio_scales_every_length_in_pixels_and_nothing_else() {
    let dither = Dither::construct("", vec![("scale", Value::Float(3.0))]).unwrap();
    let material = Material::construct(
        "hatching",
        vec![
            ("spacing", Value::Float(10.0)),
            ("width", Value::Float(1.5)),
            ("dither", Value::setting(Setting::Dither(dither))),
        ],
    )
    .unwrap();
    let outlines = Outlines::construct(
        "",
        vec![
            ("width", Value::Float(2.0)),
            ("taper", Value::Float(4.0)),
            ("crease_angle", Value::Float(40.0)),
        ],
    )
    .unwrap();
    let options = RenderOptions::construct(
        "",
        vec![
            ("material", Value::setting(Setting::Material(material.clone()))),
            ("outlines", Value::setting(Setting::Outlines(outlines.clone()))),
        ],
    )
    .unwrap();
    let twice = at_pixel_ratio(&options, 2.0);
    let m = &twice.material;
    assert_eq!((m.get("spacing"), m.get("width")), (Value::Float(20.0), Value::Float(3.0)));
    assert_eq!(m.effects.dither.map(|d| d.scale), Some(6.0));
    let o = twice.outlines.as_ref().unwrap();
    assert!(o.styles.iter().flatten().all(|s| s.width == 4.0), "{:?}", o.styles);
    assert_eq!((o.stroke_width.taper, o.crease_angle), (8.0, 40.0));
    // every other field as it was; the ratio 1 changes nothing
    let back = at_pixel_ratio(&twice, 0.5);
    assert_eq!(back, options);
    assert_eq!(at_pixel_ratio(&options, 1.0), options);
    // the paper's grain too, and nothing is marked that is not in pixels
    use crate::render::effects::paper::settings::Paper;
    let paper = Paper::construct("", vec![("scale", Value::Float(2.0))]).unwrap();
    assert_eq!(at_pixel_ratio(&paper, 1.5).scale, 3.0);
    assert!(
        !parameter::<Outlines>("depth_jump").unwrap().pixels,
        "pixel footprints are a tolerance, not a length"
    );
}

#[test]
fn a_declared_field_missing_from_a_state_takes_its_default_and_an_unknown_name_is_refused() {
    // a state saved before `strength` existed
    let old: Shadows = serde_json::from_str(r#"{"size": 1024, "bias": 2.0, "filter": "none"}"#).unwrap();
    assert_eq!(old, Shadows { size: 1024, bias: 2.0, strength: Shadows::default().strength, ..old });
    let mut s = Shadows::default();
    let e = s.set("strenght", Value::Float(0.5)).unwrap_err();
    assert!(e.to_string().contains("did you mean 'strength'"), "{e}");
    let mut light = Light::default();
    assert!(light.set("position", Value::Triple([0.0; 3])).unwrap_err().to_string().starts_with("position"));
}

#[test]
fn every_number_is_checked_against_its_described_rule() {
    fn refuses<T: Described>(field: &str, x: f64) {
        let mut v = T::start(T::CONSTRUCTORS[0].name);
        v.set(field, Value::Float(x)).unwrap();
        let e = v.check().unwrap_err();
        assert!(e.to_string().starts_with(field), "{}.{field}: {e}", T::CLASS);
    }
    refuses::<Shadows>("bias", -1.0);
    refuses::<Shadows>("bias", f64::INFINITY);
    refuses::<Camera>("margin", 0.0);
    refuses::<Camera>("turn", f64::NAN);
    refuses::<Light>("intensity", -0.5);
    refuses::<Outlines>("depth_jump", -1.0);
    refuses::<LineStyle>("width", 0.0);
    refuses::<RenderOptions>("pixel_ratio", 100.0);
}
