//! Label placement without overlap: greedy, in order of importance, each
//! label at the first of a list of positions around its point whose box
//! hits no label placed before it and stays in the plot; a label with no
//! free position is left out (the legend has every vessel). Decision 36.

/// A box in pixels, `x` right and `y` down.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct PixelBox {
    /// Left edge.
    pub(super) x0: f64,
    /// Top edge.
    pub(super) y0: f64,
    /// Right edge.
    pub(super) x1: f64,
    /// Bottom edge.
    pub(super) y1: f64,
}

impl PixelBox {
    /// Whether the two boxes share any area.
    #[must_use]
    pub(super) fn overlaps(&self, other: &PixelBox) -> bool {
        self.x0 < other.x1 && other.x0 < self.x1 && self.y0 < other.y1 && other.y0 < self.y1
    }

    /// Whether `self` lies wholly inside `outer`.
    #[must_use]
    fn inside(&self, outer: &PixelBox) -> bool {
        self.x0 >= outer.x0 && self.x1 <= outer.x1 && self.y0 >= outer.y0 && self.y1 <= outer.y1
    }
}

/// Where a label went: the top left of its text, pixels, and whether it sits
/// away from its point (then a leader line joins them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Placement {
    /// Top left corner of the text box.
    pub(super) top_left_px: (f64, f64),
    /// Whether the label is on the outer ring, far enough to need a leader.
    pub(super) leader: bool,
}

/// Gap between a point and its label, pixels.
const GAP_PX: f64 = 6.0;

/// Places labels one after the other in a plot.
#[derive(Debug, Clone)]
pub(super) struct LabelPlacer {
    bounds: PixelBox,
    taken: Vec<PixelBox>,
}

impl LabelPlacer {
    /// A placer for labels inside `bounds` (the plotting area).
    #[must_use]
    pub(super) fn new(bounds: PixelBox) -> Self {
        Self {
            bounds,
            taken: Vec::new(),
        }
    }

    /// Marks `area` as taken, so that no label covers it (a legend box, an
    /// important mark).
    pub(super) fn block(&mut self, area: PixelBox) {
        self.taken.push(area);
    }

    /// The boxes taken so far: blocked areas and placed labels.
    #[cfg(test)]
    fn taken(&self) -> &[PixelBox] {
        &self.taken
    }

    /// Places a label `width_px` by `height_px` next to `anchor_px`: right
    /// above, right below, left above, left below, above, below, then the
    /// same around a ring three and six times as far. `None` when every
    /// position hits a label or leaves the plot.
    pub(super) fn place(
        &mut self,
        anchor_px: (f64, f64),
        (width_px, height_px): (f64, f64),
    ) -> Option<Placement> {
        let (x, y) = anchor_px;
        for (ring, scale) in [1.0, 3.0, 6.0].into_iter().enumerate() {
            let gap = GAP_PX * scale;
            let candidates = [
                (x + gap, y - gap - height_px),
                (x + gap, y + gap),
                (x - gap - width_px, y - gap - height_px),
                (x - gap - width_px, y + gap),
                (x - 0.5 * width_px, y - gap - height_px),
                (x - 0.5 * width_px, y + gap),
                (x + gap, y - 0.5 * height_px),
                (x - gap - width_px, y - 0.5 * height_px),
            ];
            for (x0, y0) in candidates {
                let candidate = PixelBox {
                    x0,
                    y0,
                    x1: x0 + width_px,
                    y1: y0 + height_px,
                };
                if candidate.inside(&self.bounds)
                    && !self.taken.iter().any(|box_| box_.overlaps(&candidate))
                {
                    self.taken.push(candidate);
                    return Some(Placement {
                        top_left_px: (x0, y0),
                        leader: ring > 0,
                    });
                }
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bounds() -> PixelBox {
        PixelBox {
            x0: 0.0,
            y0: 0.0,
            x1: 400.0,
            y1: 300.0,
        }
    }

    #[test]
    fn piled_up_labels_do_not_overlap() {
        let mut placer = LabelPlacer::new(bounds());
        // Twenty labels on one point and twenty in a tight cluster, as at
        // the closest approaches of a TSS crossing.
        let mut count = 0;
        for i in 0..40 {
            let anchor = if i < 20 {
                (200.0, 150.0)
            } else {
                (100.0 + f64::from(i % 5), 80.0 + f64::from(i % 3))
            };
            count += usize::from(placer.place(anchor, (70.0, 14.0)).is_some());
        }
        assert!(count >= 20, "only {count} placed");
        let boxes = placer.taken();
        for (i, first) in boxes.iter().enumerate() {
            assert!(first.inside(&bounds()));
            for second in &boxes[i + 1..] {
                assert!(!first.overlaps(second), "{first:?} overlaps {second:?}");
            }
        }
    }

    #[test]
    fn first_label_goes_right_above_and_blocked_areas_are_kept_free() {
        let mut placer = LabelPlacer::new(bounds());
        let first = placer.place((100.0, 100.0), (50.0, 10.0)).unwrap();
        assert_eq!(first.top_left_px, (106.0, 84.0));
        assert!(!first.leader);
        let mut placer = LabelPlacer::new(bounds());
        placer.block(PixelBox {
            x0: 0.0,
            y0: 0.0,
            x1: 400.0,
            y1: 300.0,
        });
        assert_eq!(placer.place((100.0, 100.0), (50.0, 10.0)), None);
    }

    #[test]
    fn labels_stay_in_the_plot() {
        let mut placer = LabelPlacer::new(bounds());
        let corner = placer.place((399.0, 1.0), (50.0, 10.0)).unwrap();
        assert!(corner.top_left_px.0 + 50.0 <= 400.0 && corner.top_left_px.1 >= 0.0);
        assert_eq!(placer.place((200.0, 150.0), (500.0, 10.0)), None);
    }
}
