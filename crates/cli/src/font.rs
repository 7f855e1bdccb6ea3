//! The font PNG text is drawn with: `DejaVu` Sans, bundled in the binary
//! (`assets/DejaVuSans.ttf`, licence in `assets/DejaVuSans-LICENSE.txt`), so
//! that plots read the same on a machine with no system fonts. SVG files only
//! name the family (`sans-serif`); the viewer picks the font.

use plotters::style::{FontStyle, register_font};
use std::sync::Once;

/// The family name plots use for all text.
pub(crate) const FAMILY: &str = "sans-serif";

/// The bytes of `DejaVu` Sans 2.37.
pub(crate) static DEJAVU_SANS: &[u8] = include_bytes!("../assets/DejaVuSans.ttf");

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

#[cfg(test)]
mod tests {
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
    }
}
