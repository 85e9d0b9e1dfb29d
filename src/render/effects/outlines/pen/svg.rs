//! A line drawing as an SVG document of the image's size (pixel units): one group per set of
//! strokes, each stroke a polyline stroked at the group's width, or, where the ink's width
//! changes along it, a filled outline of that ink. Coordinates are written to a hundredth of a
//! pixel.

use std::fmt::Write;

use crate::render::color::Srgb;

/// How a group inks its strokes.
#[derive(Clone, Debug, PartialEq)]
pub enum Ink {
    /// Centre lines at one width in pixels, with round caps and joins; `dashes` (dash and gap
    /// lengths) draws them dashed, with plain caps so that dashes keep their lengths.
    Lines { width: f64, dashes: Option<[f64; 2]> },
    /// Each stroke's outline filled: the shape the line pass inks at each point's width.
    Filled,
}

/// One stroke: its points and (for `Ink::Filled`) the ink's width at each, in pixels.
#[derive(Clone, Debug, PartialEq)]
pub struct Stroke {
    pub points: Vec<[f64; 2]>,
    pub widths: Vec<f64>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Group {
    pub id: String,
    pub color: Srgb,
    pub ink: Ink,
    pub strokes: Vec<Stroke>,
}

/// The SVG document of a `width` x `height` pixel drawing made of `groups`, drawn in order.
pub fn document(width: u32, height: u32, groups: &[Group]) -> String {
    let mut out = String::new();
    out.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{height}\" \
         viewBox=\"0 0 {width} {height}\">"
    );
    for g in groups {
        let (id, color) = (escaped(&g.id), hex(g.color));
        match g.ink {
            Ink::Filled => {
                let _ =
                    writeln!(out, "<g id=\"{id}\" fill=\"{color}\" fill-rule=\"nonzero\" stroke=\"none\">");
            }
            Ink::Lines { width, dashes: None } => {
                let _ = writeln!(
                    out,
                    "<g id=\"{id}\" fill=\"none\" stroke=\"{color}\" stroke-width=\"{}\" \
                     stroke-linecap=\"round\" stroke-linejoin=\"round\">",
                    general(width)
                );
            }
            Ink::Lines { width, dashes: Some([dash, gap]) } => {
                let _ = writeln!(
                    out,
                    "<g id=\"{id}\" fill=\"none\" stroke=\"{color}\" stroke-width=\"{}\" \
                     stroke-dasharray=\"{} {}\">",
                    general(width),
                    general(dash),
                    general(gap)
                );
            }
        }
        for s in &g.strokes {
            match g.ink {
                Ink::Filled => {
                    out.push_str("<path d=\"");
                    outline_path(&mut out, &s.points, &s.widths);
                    out.push_str("\"/>\n");
                }
                Ink::Lines { .. } => {
                    out.push_str("<polyline points=\"");
                    for (i, p) in s.points.iter().enumerate() {
                        let _ = write!(out, "{}{:.2},{:.2}", if i > 0 { " " } else { "" }, p[0], p[1]);
                    }
                    out.push_str("\"/>\n");
                }
            }
        }
        out.push_str("</g>\n");
    }
    out.push_str("</svg>\n");
    out
}

/// Writes the SVG path data of the ink of a stroke whose width (pixels, per point) varies along
/// it, the shape the line pass inks: each segment a band whose half width goes linearly from
/// one end's to the other's, closed by half discs at both ends (so segments join round and the
/// stroke ends round). Every piece winds the same way, so under the nonzero fill rule they are
/// one shape where they overlap.
pub fn outline_path(out: &mut String, points: &[[f64; 2]], widths: &[f64]) {
    let disc = |out: &mut String, c: [f64; 2], r: f64| {
        let _ = write!(
            out,
            "M{:.2},{:.2}A{r:.2},{r:.2} 0 0 1 {:.2},{:.2}A{r:.2},{r:.2} 0 0 1 {:.2},{:.2}Z",
            c[0] - r,
            c[1],
            c[0] + r,
            c[1],
            c[0] - r,
            c[1]
        );
    };
    let r: Vec<f64> = widths.iter().map(|w| 0.5 * w).collect();
    if points.len() == 1 {
        disc(out, points[0], r[0]);
        return;
    }
    for (i, pair) in points.windows(2).enumerate() {
        let (a, b, ra, rb) = (pair[0], pair[1], r[i], r[i + 1]);
        let d = [b[0] - a[0], b[1] - a[1]];
        let length = d[0].hypot(d[1]);
        if length == 0.0 {
            disc(out, a, ra.max(rb));
            continue;
        }
        let (nx, ny) = (-d[1] / length, d[0] / length);
        let _ = write!(
            out,
            "M{:.2},{:.2}A{ra:.2},{ra:.2} 0 0 1 {:.2},{:.2}L{:.2},{:.2}A{rb:.2},{rb:.2} 0 0 1 {:.2},{:.2}Z",
            a[0] + nx * ra,
            a[1] + ny * ra,
            a[0] - nx * ra,
            a[1] - ny * ra,
            b[0] - nx * rb,
            b[1] - ny * rb,
            b[0] + nx * rb,
            b[1] + ny * rb
        );
    }
}

/// `#rrggbb` of an sRGB colour, each channel rounded to the nearest of 256 codes (ties to even).
fn hex(c: Srgb) -> String {
    let code = |x: f64| (x * 255.0).round_ties_even().clamp(0.0, 255.0) as u8;
    format!("#{:02x}{:02x}{:02x}", code(c[0]), code(c[1]), code(c[2]))
}

/// A number as C's `%g` writes it (six significant digits, no trailing zeros, an exponent only
/// where the number is very large or small): `1.5`, `6`, `0.3` for the float32 0.3.
fn general(x: f64) -> String {
    const DIGITS: i32 = 6;
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let sci = format!("{:.*e}", (DIGITS - 1) as usize, x);
    let (mantissa, exponent) = sci.split_once('e').unwrap_or((&sci, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    let trim = |s: &str| {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s.to_string()
        }
    };
    if (-4..DIGITS).contains(&exponent) {
        trim(&format!("{:.*}", (DIGITS - 1 - exponent) as usize, x))
    } else {
        format!("{}e{}{:02}", trim(mantissa), if exponent < 0 { '-' } else { '+' }, exponent.abs())
    }
}

/// `text` safe inside a double-quoted XML attribute.
fn escaped(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stroke(points: &[[f64; 2]], widths: &[f64]) -> Stroke {
        Stroke { points: points.to_vec(), widths: widths.to_vec() }
    }

    #[test]
    fn a_document_has_a_group_per_kind_of_ink() {
        let groups = [
            Group {
                id: "hidden".into(),
                color: [154.0 / 255.0; 3],
                ink: Ink::Lines { width: 1.0, dashes: Some([4.0, 3.0]) },
                strokes: vec![stroke(&[[0.0, 0.0], [1.005, 2.5]], &[])],
            },
            Group {
                id: "silhouette".into(),
                color: [1.0, 0.5, 0.0],
                ink: Ink::Lines { width: 0.30000001192092896, dashes: None },
                strokes: vec![stroke(&[[0.125, -0.001]], &[])],
            },
            Group {
                id: "ridge".into(),
                color: [0.0; 3],
                ink: Ink::Filled,
                strokes: vec![stroke(&[[1.0, 1.0]], &[2.0])],
            },
        ];
        let expected = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
            <svg xmlns=\"http://www.w3.org/2000/svg\" width=\"40\" height=\"30\" viewBox=\"0 0 40 30\">\n\
            <g id=\"hidden\" fill=\"none\" stroke=\"#9a9a9a\" stroke-width=\"1\" stroke-dasharray=\"4 3\">\n\
            <polyline points=\"0.00,0.00 1.00,2.50\"/>\n\
            </g>\n\
            <g id=\"silhouette\" fill=\"none\" stroke=\"#ff8000\" stroke-width=\"0.3\" \
            stroke-linecap=\"round\" stroke-linejoin=\"round\">\n\
            <polyline points=\"0.12,-0.00\"/>\n\
            </g>\n\
            <g id=\"ridge\" fill=\"#000000\" fill-rule=\"nonzero\" stroke=\"none\">\n\
            <path d=\"M0.00,1.00A1.00,1.00 0 0 1 2.00,1.00A1.00,1.00 0 0 1 0.00,1.00Z\"/>\n\
            </g>\n\
            </svg>\n";
        assert_eq!(document(40, 30, &groups), expected);
    }

    #[test]
    fn a_segment_is_a_band_between_half_discs_of_its_ends_widths() {
        let mut d = String::new();
        outline_path(&mut d, &[[0.0, 0.0], [10.0, 0.0], [10.0, 0.0]], &[2.0, 4.0, 1.0]);
        assert_eq!(
            d,
            "M0.00,1.00A1.00,1.00 0 0 1 0.00,-1.00L10.00,-2.00A2.00,2.00 0 0 1 10.00,2.00Z\
             M8.00,0.00A2.00,2.00 0 0 1 12.00,0.00A2.00,2.00 0 0 1 8.00,0.00Z"
        );
    }

    #[test]
    fn numbers_are_written_as_percent_g_does() {
        for (x, text) in [
            (1.5, "1.5"),
            (6.0, "6"),
            (0.30000001192092896, "0.3"),
            (1234567.0, "1.23457e+06"),
            (0.0001, "0.0001"),
            (0.00001, "1e-05"),
            (-2.25, "-2.25"),
            (100000.0, "100000"),
            (0.0, "0"),
        ] {
            assert_eq!(general(x), text);
        }
        assert_eq!(escaped("a\"<b>&"), "a&quot;&lt;b&gt;&amp;");
        assert_eq!(hex([0.5, 1.0 / 510.0, 1.0]), "#8000ff", "127.5 and 0.5 round to even");
    }
}
