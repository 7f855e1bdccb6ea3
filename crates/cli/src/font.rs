//! The font PNG text is drawn with: `DejaVu` Sans, bundled in the binary
//! (`assets/DejaVuSans.ttf`, licence in `assets/DejaVuSans-LICENSE.txt`), so
//! that plots read the same on a machine with no system fonts. SVG files only
//! name the family (`sans-serif`); the viewer picks the font.
//!
//! PNG text goes through [`GlyphText`], a wrapper of the bitmap backend that
//! draws each glyph at its pen position plus its left side bearing. plotters
//! 0.3.7 (`style/font/ab_glyph.rs`) places each glyph's ink box at the pen
//! position and drops the bearing, so narrow glyphs with wide bearings ("1",
//! "I", "r") sit too far left and leave a gap after them ("TS1 0",
//! "VORR T"): decision 36.

use ab_glyph::{Font, FontRef, PxScale, ScaleFont, point};
use plotters::style::{FontStyle, register_font};
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
};
use std::sync::{Once, OnceLock};

/// The family name plots use for all text.
pub(crate) const FAMILY: &str = "sans-serif";

/// The bytes of `DejaVu` Sans 2.37.
pub(crate) static DEJAVU_SANS: &[u8] = include_bytes!("../assets/DejaVuSans.ttf");

/// plotters' text box height is the font size over this (its
/// `estimate_layout`); kept so that layouts measured by plotters fit the text.
const BOX_HEIGHT_DIVISOR: f64 = 1.24;

/// Registers the bundled font for every style of [`FAMILY`] (bold and italic
/// fall back to the regular face). Idempotent; call before drawing.
pub(crate) fn register() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        // The bytes are a valid TrueType font, checked by the tests; should
        // registration ever fail, text is left out of PNG plots rather than
        // the program stopping.
        let _ = register_font(FAMILY, FontStyle::Normal, DEJAVU_SANS);
    });
}

/// The bundled font, parsed once; `None` if the bytes were not a font (the
/// tests check they are).
fn bundled() -> Option<&'static FontRef<'static>> {
    static FONT: OnceLock<Option<FontRef<'static>>> = OnceLock::new();
    FONT.get_or_init(|| FontRef::try_from_slice(DEJAVU_SANS).ok())
        .as_ref()
}

/// The width of `text` at `size_px`, pixels: the sum of the advances and
/// kerning pairs, as plotters measures it for layout.
#[must_use]
pub(crate) fn text_width_px(text: &str, size_px: f64) -> f64 {
    let Some(font) = bundled() else {
        return 0.0;
    };
    #[expect(
        clippy::cast_possible_truncation,
        reason = "font sizes are a few dozen pixels"
    )]
    let scaled = font.as_scaled(PxScale::from(size_px as f32));
    let mut width = 0.0_f32;
    let mut previous = None;
    for c in text.chars() {
        let id = scaled.glyph_id(c);
        if let Some(previous) = previous {
            width += scaled.kern(previous, id);
        }
        width += scaled.h_advance(id);
        previous = Some(id);
    }
    f64::from(width)
}

/// The height of a line of text at `size_px`, pixels (plotters' text box).
#[must_use]
pub(crate) fn text_height_px(size_px: f64) -> f64 {
    size_px / BOX_HEIGHT_DIVISOR
}

/// The ink of `text` at `size_px`: `(x, y, coverage)` per pixel, relative to
/// the top left of its text box ([`text_width_px`] by [`text_height_px`]).
/// Each glyph's outline is placed at the pen position (advances and kerning)
/// on one baseline, so its side bearings are kept; the baseline puts the
/// capitals in the middle of the box, so that centred labels look centred.
#[must_use]
pub(crate) fn glyph_coverage(text: &str, size_px: f64) -> Vec<(i32, i32, f32)> {
    let Some(font) = bundled() else {
        return Vec::new();
    };
    #[expect(
        clippy::cast_possible_truncation,
        reason = "font sizes are a few dozen pixels"
    )]
    let scale = PxScale::from(size_px as f32);
    let scaled = font.as_scaled(scale);
    let cap_height_px = font
        .outline(scaled.glyph_id('H'))
        .map_or(scaled.ascent(), |outline| {
            // From the baseline to the top of "H": its outline's height (the
            // bounds are y-up with min.y the top, so take the size).
            (outline.bounds.max.y - outline.bounds.min.y).abs() * scaled.v_scale_factor()
        });
    #[expect(
        clippy::cast_possible_truncation,
        reason = "a text box a few dozen pixels high"
    )]
    let baseline_px = (0.5 * (text_height_px(size_px) + f64::from(cap_height_px))) as f32;
    let mut ink = Vec::new();
    let mut pen_px = 0.0_f32;
    let mut previous = None;
    for c in text.chars() {
        let id = scaled.glyph_id(c);
        if let Some(previous) = previous {
            pen_px += scaled.kern(previous, id);
        }
        let glyph = id.with_scale_and_position(scale, point(pen_px, baseline_px));
        if let Some(outline) = font.outline_glyph(glyph) {
            let bounds = outline.px_bounds();
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_possible_wrap,
                reason = "pixel positions within a plot"
            )]
            outline.draw(|x, y, coverage| {
                ink.push((
                    bounds.min.x as i32 + x as i32,
                    bounds.min.y as i32 + y as i32,
                    coverage,
                ));
            });
        }
        pen_px += scaled.h_advance(id);
        previous = Some(id);
    }
    ink
}

/// A drawing backend that draws text with [`glyph_coverage`] and everything
/// else with the backend it wraps (the PNG backend).
pub(crate) struct GlyphText<DB>(pub(crate) DB);

impl<DB: DrawingBackend> DrawingBackend for GlyphText<DB> {
    type ErrorType = DB::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        self.0.get_size()
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.ensure_prepared()
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.present()
    }

    fn draw_pixel(
        &mut self,
        point: BackendCoord,
        color: BackendColor,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.draw_pixel(point, color)
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.draw_line(from, to, style)
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.draw_rect(upper_left, bottom_right, style, fill)
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.draw_path(path, style)
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.draw_circle(center, radius, style, fill)
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.fill_polygon(vert, style)
    }

    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        size: (u32, u32),
        src: &[u8],
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.blit_bitmap(pos, size, src)
    }

    fn estimate_text_size<TStyle: BackendTextStyle>(
        &self,
        text: &str,
        style: &TStyle,
    ) -> Result<(u32, u32), DrawingErrorKind<Self::ErrorType>> {
        let (width, height) = text_box_px(text, style.size());
        Ok((width.unsigned_abs(), height.unsigned_abs()))
    }

    /// The text anchored and turned as plotters' default `draw_text` does,
    /// with the glyphs of [`glyph_coverage`]; bold is drawn twice, one pixel
    /// apart (only the regular face is bundled).
    fn draw_text<TStyle: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &TStyle,
        pos: BackendCoord,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        let (width, height) = text_box_px(text, style.size());
        let dx = match style.anchor().h_pos {
            HPos::Left => 0,
            HPos::Right => -width,
            HPos::Center => -width / 2,
        };
        let dy = match style.anchor().v_pos {
            VPos::Top => 0,
            VPos::Center => -height / 2,
            VPos::Bottom => -height,
        };
        let strokes: &[i32] = if matches!(style.style(), FontStyle::Bold) {
            &[0, 1]
        } else {
            &[0]
        };
        let transform = style.transform();
        let (canvas_w, canvas_h) = self.get_size();
        let inside = |(x, y): (i32, i32)| {
            u32::try_from(x).is_ok_and(|x| x < canvas_w)
                && u32::try_from(y).is_ok_and(|y| y < canvas_h)
        };
        for (x, y, coverage) in glyph_coverage(text, style.size()) {
            for stroke in strokes {
                let (x, y) = transform.transform(x + stroke + dx, y + dy);
                let at = (pos.0 + x, pos.1 + y);
                if inside(at) {
                    let ink = BackendColor {
                        alpha: color.alpha * f64::from(coverage),
                        rgb: color.rgb,
                    };
                    self.0.draw_pixel(at, ink)?;
                }
            }
        }
        Ok(())
    }
}

/// The text box of `text` at `size_px`, whole pixels, as plotters measures it
/// (so that the layouts plotters computes fit what is drawn).
fn text_box_px(text: &str, size_px: f64) -> (i32, i32) {
    #[expect(
        clippy::cast_possible_truncation,
        reason = "a text box within a plot, truncated as plotters does"
    )]
    let size = (
        text_width_px(text, size_px) as i32,
        text_height_px(size_px) as i32,
    );
    size
}

#[cfg(test)]
mod tests {
    use super::*;
    use plotters::prelude::*;

    #[test]
    fn bundled_font_registers() {
        assert!(
            plotters::style::register_font(
                super::FAMILY,
                plotters::style::FontStyle::Normal,
                super::DEJAVU_SANS
            )
            .is_ok()
        );
        assert!(bundled().is_some());
    }

    /// The columns of `pixels` (RGB, `width` wide) with ink darker than mid grey.
    fn inked_columns(pixels: &[u8], width: usize) -> Vec<bool> {
        let mut columns = vec![false; width];
        for (index, rgb) in pixels.chunks(3).enumerate() {
            if rgb.iter().map(|&c| u32::from(c)).sum::<u32>() < 3 * 128 {
                columns[index % width] = true;
            }
        }
        columns
    }

    /// The widths of the blank runs between inked columns.
    fn gaps(columns: &[bool]) -> Vec<usize> {
        let first = columns.iter().position(|&c| c).unwrap_or(0);
        let last = columns.iter().rposition(|&c| c).unwrap_or(0);
        let mut gaps = Vec::new();
        let mut run = 0;
        for &inked in &columns[first..=last] {
            if inked {
                if run > 0 {
                    gaps.push(run);
                }
                run = 0;
            } else {
                run += 1;
            }
        }
        gaps
    }

    /// "TS10" drawn at 40 px by `draw` on a white bitmap; the blank gaps
    /// between its glyphs, pixels.
    fn ts10_gaps(glyph_text: bool) -> Vec<usize> {
        const W: u32 = 200;
        const H: u32 = 60;
        register();
        let mut pixels = vec![255_u8; (W * H * 3) as usize];
        {
            let style = (FAMILY, 40).into_font().color(&BLACK);
            if glyph_text {
                let root =
                    GlyphText(BitMapBackend::with_buffer(&mut pixels, (W, H))).into_drawing_area();
                root.draw(&Text::new("TS10", (10, 10), style)).unwrap();
                root.present().unwrap();
            } else {
                let root = BitMapBackend::with_buffer(&mut pixels, (W, H)).into_drawing_area();
                root.draw(&Text::new("TS10", (10, 10), style)).unwrap();
                root.present().unwrap();
            }
        }
        gaps(&inked_columns(&pixels, W as usize))
    }

    /// The blank gap between the ink of `a` and `b` set side by side at
    /// 40 px, as the font's metrics say: the right bearing of `a`, the
    /// kerning and the left bearing of `b`.
    fn metric_gap(a: char, b: char) -> f32 {
        let font = bundled().unwrap();
        let scaled = font.as_scaled(PxScale::from(40.0));
        let bounds = |c: char| font.outline(font.glyph_id(c)).unwrap().bounds;
        let factor = scaled.h_scale_factor();
        scaled.h_advance(font.glyph_id(a)) - bounds(a).max.x * factor
            + bounds(b).min.x * factor
            + scaled.kern(font.glyph_id(a), font.glyph_id(b))
    }

    /// Each gap between the glyphs of "TS10" is the font's, within a pixel
    /// or so. plotters' own rendering drops the left bearings: "1" moves
    /// left onto "S" and stands apart from "0" ("TS1 0").
    #[test]
    fn ts10_has_no_gap() {
        let expected = [
            metric_gap('T', 'S'),
            metric_gap('S', '1'),
            metric_gap('1', '0'),
        ];
        let fixed = ts10_gaps(true);
        assert_eq!(fixed.len(), 3, "T, S, 1 and 0 apart: {fixed:?}");
        for (gap, expected) in fixed.iter().zip(expected) {
            #[expect(clippy::cast_precision_loss, reason = "a gap of a few pixels")]
            let gap = *gap as f32;
            assert!(
                (gap - expected).abs() <= 1.5,
                "gaps {fixed:?} px, the font says {expected:?} px"
            );
        }
        let plotters_own = ts10_gaps(false);
        assert_ne!(
            plotters_own, fixed,
            "plotters' own text has the gaps right now; GlyphText can go"
        );
    }

    #[test]
    fn width_is_the_sum_of_advances() {
        let one = text_width_px("1", 20.0);
        assert!(one > 0.0);
        assert!((text_width_px("111", 20.0) - 3.0 * one).abs() < 1e-3);
        assert!((text_height_px(24.8) - 20.0).abs() < 1e-9);
    }

    #[test]
    fn coverage_lies_in_the_text_box() {
        let ink = glyph_coverage("Hx", 20.0);
        assert!(!ink.is_empty());
        let width = text_width_px("Hx", 20.0);
        #[expect(clippy::cast_possible_truncation, reason = "a small box")]
        let right = width.ceil() as i32;
        let (x_min, x_max) = (ink.iter().map(|p| p.0).min(), ink.iter().map(|p| p.0).max());
        let (y_min, y_max) = (ink.iter().map(|p| p.1).min(), ink.iter().map(|p| p.1).max());
        assert!(
            x_min >= Some(0) && x_max <= Some(right) && y_min >= Some(0) && y_max < Some(17),
            "x {x_min:?}-{x_max:?} of {right}, y {y_min:?}-{y_max:?}"
        );
    }
}
