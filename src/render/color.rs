//! Colours. They are given in sRGB (as on screen and in image files), either as three numbers
//! in [0, 1] or as a `#rrggbb` string; shading is computed in linear light and the colour target
//! encodes back to sRGB on store.

use crate::error::{Error, Result};

/// An sRGB colour with channels in [0, 1].
pub type Srgb = [f64; 3];

/// The sRGB transfer function's inverse (IEC 61966-2-1), for one channel in [0, 1].
pub fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The sRGB transfer function, for one channel; input is clamped to [0, 1] first.
pub fn linear_to_srgb(c: f64) -> f64 {
    let c = c.clamp(0.0, 1.0);
    if c <= 0.0031308 {
        c * 12.92
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
}

/// The 8-bit sRGB code of a linear value, as an sRGB colour target stores it.
pub fn linear_to_srgb8(c: f64) -> u8 {
    (linear_to_srgb(c) * 255.0).round() as u8
}

/// Decodes an sRGB colour to linear light, in the precision the shaders use.
pub fn to_linear(c: Srgb) -> [f32; 3] {
    c.map(|v| srgb_to_linear(v) as f32)
}

/// `c` with its light scaled by `k` (in linear light), as sRGB: "10% of the colour".
pub fn scaled(c: Srgb, k: f64) -> Srgb {
    c.map(|v| linear_to_srgb(srgb_to_linear(v) * k))
}

/// Checks channels: finite and within [0, 1]. Values above 1 are refused rather than clipped,
/// since they usually mean 0-255 codes (divide by 255).
pub fn check_unit(arg: &str, channels: &[f64]) -> Result<()> {
    if let Some(bad) = channels.iter().find(|v| !(v.is_finite() && (0.0..=1.0).contains(*v))) {
        let hint = if bad.is_finite() && *bad > 1.0 { " (for 0-255 codes, divide by 255)" } else { "" };
        return Err(Error::invalid(arg, format!("channels must be in [0, 1], got {channels:?}{hint}")));
    }
    Ok(())
}

/// An sRGB colour from three channels in [0, 1].
pub fn from_channels(arg: &str, channels: &[f64]) -> Result<Srgb> {
    if channels.len() != 3 {
        return Err(Error::invalid(arg, format!("expected 3 channels, got {}", channels.len())));
    }
    check_unit(arg, channels)?;
    Ok([channels[0], channels[1], channels[2]])
}

/// An sRGB colour with alpha from three or four channels in [0, 1] (alpha 1 when not given).
pub fn rgba_from_channels(arg: &str, c: &[f64]) -> Result<[f64; 4]> {
    if !(c.len() == 3 || c.len() == 4) {
        return Err(Error::invalid(arg, format!("expected 3 or 4 channels, got {}", c.len())));
    }
    check_unit(arg, c)?;
    Ok([c[0], c[1], c[2], c.get(3).copied().unwrap_or(1.0)])
}

/// Parses `#rrggbb` (the `#` is optional) or `#rrggbbaa` into channels in [0, 1].
pub fn parse_hex(arg: &str, text: &str) -> Result<Vec<f64>> {
    let hex = text.trim().trim_start_matches('#');
    let bad = || Error::invalid(arg, format!("expected a colour '#rrggbb' (or '#rrggbbaa'), got {text:?}"));
    if !(hex.len() == 6 || hex.len() == 8) || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return Err(bad());
    }
    (0..hex.len() / 2)
        .map(|i| u8::from_str_radix(&hex[2 * i..2 * i + 2], 16).map(|b| b as f64 / 255.0).map_err(|_| bad()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_8bit_code_round_trips() {
        for code in 0..=255u8 {
            let lin = srgb_to_linear(code as f64 / 255.0);
            assert_eq!(linear_to_srgb8(lin), code);
        }
    }

    #[test]
    fn hex_and_ranges() {
        assert_eq!(parse_hex("c", "#ff0080").unwrap(), vec![1.0, 0.0, 128.0 / 255.0]);
        assert_eq!(parse_hex("c", "00000000").unwrap().len(), 4);
        assert!(parse_hex("c", "#fff").is_err() && parse_hex("c", "#gg0000").is_err());
        assert!(from_channels("c", &[255.0, 128.0, 0.0]).unwrap_err().to_string().contains("255"));
        assert!(from_channels("c", &[f64::NAN, 0.0, 0.0]).is_err());
        assert!((scaled([1.0, 0.5, 0.0], 1.0)[1] - 0.5).abs() < 1e-12);
    }
}
