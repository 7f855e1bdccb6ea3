//! Target colours: 20 distinct ones, then a ramp of hues of one lightness
//! pair and chroma in CIELAB; ownship is black and no target colour is near
//! it (decision 36).

use plotters::style::RGBColor;

/// The first 20 target colours: Tableau 10 (the colours of earlier plots),
/// then ten picked greedily from a 16-level sRGB grid to lie farthest, in
/// CIELAB, from these, from black (ownship), white (the paper) and the
/// clearance red, with lightness 35-75 and chroma 25-65 (no neon).
/// Every pair is at least 27 CIELAB units apart (tested).
const DISTINCT: [RGBColor; 20] = [
    RGBColor(214, 39, 40),
    RGBColor(31, 119, 180),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(188, 189, 34),
    RGBColor(127, 127, 127),
    RGBColor(102, 102, 17),
    RGBColor(0, 119, 85),
    RGBColor(238, 170, 119),
    RGBColor(170, 0, 85),
    RGBColor(153, 187, 119),
    RGBColor(255, 119, 136),
    RGBColor(153, 85, 0),
    RGBColor(0, 204, 153),
    RGBColor(187, 170, 221),
    RGBColor(0, 85, 187),
];

/// How many targets get a colour of their own.
#[cfg(test)]
const DISTINCT_COLOURS: usize = DISTINCT.len();

/// The golden angle, degrees: successive hues of the ramp are this far apart,
/// so that neighbours in the target list never look alike.
const GOLDEN_ANGLE_DEG: f64 = 137.507_764;

/// The ramp's CIELAB chroma.
const RAMP_CHROMA: f64 = 45.0;

/// The ramp's two CIELAB lightnesses, alternated.
const RAMP_LIGHTNESS: [f64; 2] = [48.0, 62.0];

/// The colour of target `index` (from 0) in every plot: one of
/// [`DISTINCT_COLOURS`] distinct colours, then the ramp.
#[must_use]
pub(crate) fn target_colour(index: usize) -> RGBColor {
    if let Some(colour) = DISTINCT.get(index) {
        return *colour;
    }
    let k = index - DISTINCT.len();
    #[expect(clippy::cast_precision_loss, reason = "a target index, far below 2^52")]
    let hue_rad = (20.0 + GOLDEN_ANGLE_DEG * k as f64)
        .rem_euclid(360.0)
        .to_radians();
    let lightness = RAMP_LIGHTNESS[k % RAMP_LIGHTNESS.len()];
    from_lab([
        lightness,
        RAMP_CHROMA * hue_rad.cos(),
        RAMP_CHROMA * hue_rad.sin(),
    ])
}

/// The D65 white point, CIE XYZ.
const WHITE_XYZ: [f64; 3] = [0.950_47, 1.0, 1.088_83];

/// sRGB (0-255) to CIELAB (D65).
#[cfg(test)]
fn to_lab(colour: RGBColor) -> [f64; 3] {
    let linear = |c: u8| {
        let c = f64::from(c) / 255.0;
        if c <= 0.040_45 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    };
    let (r, g, b) = (linear(colour.0), linear(colour.1), linear(colour.2));
    let xyz = [
        0.412_4 * r + 0.357_6 * g + 0.180_5 * b,
        0.212_6 * r + 0.715_2 * g + 0.072_2 * b,
        0.019_3 * r + 0.119_2 * g + 0.950_5 * b,
    ];
    let f = |t: f64| {
        if t > 216.0 / 24389.0 {
            t.cbrt()
        } else {
            (24389.0 / 27.0 * t + 16.0) / 116.0
        }
    };
    let [fx, fy, fz] = [0, 1, 2].map(|i| f(xyz[i] / WHITE_XYZ[i]));
    [116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)]
}

/// CIELAB (D65) to sRGB, clamped to the gamut.
#[must_use]
#[expect(
    clippy::many_single_char_names,
    reason = "the CIE formulas' own names: L*, a*, b*, x, y, z"
)]
fn from_lab([lightness, a, b]: [f64; 3]) -> RGBColor {
    let fy = (lightness + 16.0) / 116.0;
    let f_inv = |f: f64| {
        if f > 6.0 / 29.0 {
            f * f * f
        } else {
            (116.0 * f - 16.0) * 27.0 / 24389.0
        }
    };
    let [x, y, z] = [fy + a / 500.0, fy, fy - b / 200.0];
    let xyz = [
        f_inv(x) * WHITE_XYZ[0],
        f_inv(y) * WHITE_XYZ[1],
        f_inv(z) * WHITE_XYZ[2],
    ];
    let linear = [
        3.240_6 * xyz[0] - 1.537_2 * xyz[1] - 0.498_6 * xyz[2],
        -0.968_9 * xyz[0] + 1.875_8 * xyz[1] + 0.041_5 * xyz[2],
        0.055_7 * xyz[0] - 0.204_0 * xyz[1] + 1.057_0 * xyz[2],
    ];
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "clamped to 0-255 first"
    )]
    let byte = |c: f64| {
        let c = c.clamp(0.0, 1.0);
        let c = if c <= 0.003_130_8 {
            12.92 * c
        } else {
            1.055 * c.powf(1.0 / 2.4) - 0.055
        };
        (255.0 * c).round().clamp(0.0, 255.0) as u8
    };
    RGBColor(byte(linear[0]), byte(linear[1]), byte(linear[2]))
}

/// The CIE76 colour difference of two colours: the CIELAB distance.
#[cfg(test)]
fn difference(first: RGBColor, second: RGBColor) -> f64 {
    let (a, b) = (to_lab(first), to_lab(second));
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::OWNSHIP_COLOUR;

    #[test]
    fn first_twenty_are_distinct_and_far_from_ownship() {
        let colours: Vec<RGBColor> = (0..DISTINCT_COLOURS).map(target_colour).collect();
        for (i, first) in colours.iter().enumerate() {
            for second in &colours[i + 1..] {
                let delta = difference(*first, *second);
                assert!(delta >= 27.0, "{first:?} and {second:?}: {delta:.1}");
            }
            assert!(difference(*first, OWNSHIP_COLOUR) >= 45.0, "{first:?}");
            assert!(to_lab(*first)[0] <= 80.0, "{first:?} too pale on white");
        }
    }

    #[test]
    fn ramp_neighbours_differ_and_stay_visible() {
        let colours: Vec<RGBColor> = (DISTINCT_COLOURS..DISTINCT_COLOURS + 120)
            .map(target_colour)
            .collect();
        for pair in colours.windows(2) {
            assert!(difference(pair[0], pair[1]) >= 20.0, "{pair:?}");
        }
        for colour in &colours {
            assert!(difference(*colour, OWNSHIP_COLOUR) >= 40.0, "{colour:?}");
            assert!(to_lab(*colour)[0] <= 75.0, "{colour:?}");
        }
        // Not a cycle of ten: target 10 and target 0 differ, and so do 30 and 20.
        assert!(difference(target_colour(10), target_colour(0)) >= 27.0);
        assert!(difference(target_colour(30), target_colour(20)) >= 10.0);
    }

    #[test]
    fn lab_round_trips() {
        for colour in [
            RGBColor(12, 200, 99),
            RGBColor(255, 255, 255),
            RGBColor(0, 0, 0),
        ] {
            let back = from_lab(to_lab(colour));
            assert!(difference(colour, back) < 1.0, "{colour:?} -> {back:?}");
        }
        assert!(to_lab(RGBColor(255, 255, 255))[0] > 99.9);
    }
}
