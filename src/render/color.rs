//! sRGB <-> linear light. Colours are given in sRGB (as on screen and in image files); shading
//! is computed in linear light and the colour target encodes back to sRGB on store.

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

/// Decodes an sRGB RGB triple to linear light.
pub fn rgb_to_linear(c: [f64; 3]) -> [f32; 3] {
    c.map(|v| srgb_to_linear(v) as f32)
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
}
