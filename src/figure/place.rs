//! Where a figure's labels go: beside their anchor, clear of every drawn segment, point marker
//! and label placed before them.
//!
//! A label's box is estimated from its character count and the font size ([`label_box`]); the
//! renderer's real glyphs are narrower for most characters, so the estimate errs on the side
//! of room. Candidates are tried in order: the position the figure asked for, then rings of
//! positions around the anchor (right, left, above, below, the diagonals) at growing
//! distances. The first candidate that is inside the frame and touches nothing wins; when none
//! is free, the one touching fewest things. Everything is in pixels (y downwards); obstacles
//! are kept in a grid of cells, and the number of obstacle tests of one figure is bounded
//! ([`MAX_TESTS`]: past it, labels stay where the figure asked), so that a figure with
//! thousands of crowded labels is still quick.

/// The font size labels are placed for first, in pixels: the print stylesheet's 16 px
/// (html.rs), not the SVG's 13 px, so that a label clear of its neighbours on screen stays
/// clear when printed larger (its 13 px glyphs lie inside its 16 px box: same anchor and
/// baseline). Where no position is free at that size, one free at [`SVG_LABEL_FONT`] is taken.
pub(crate) const LABEL_FONT: f64 = 16.0;
/// The font size labels are drawn at in the SVG, in pixels.
const SVG_LABEL_FONT: f64 = 13.0;
/// Estimated advance of one character, as a fraction of the font size: DejaVu Sans's widest
/// digits and capitals are about 0.7 em, most letters 0.6 em or less.
pub(crate) const CHAR_EM: f64 = 0.62;
/// Ascent and descent of the label font, in em.
const ASCENT_EM: f64 = 0.78;
const DESCENT_EM: f64 = 0.26;
/// Space kept between a label and what it avoids, in pixels.
const GAP: f64 = 1.5;
/// Distances from the anchor tried, in pixels.
const RADII: [f64; 7] = [7.0, 11.0, 16.0, 23.0, 32.0, 44.0, 60.0];
/// The cost of a label outside the frame, in obstacles touched: worse than any overlap.
const OUTSIDE: usize = 1 << 20;
/// Overlaps counted per candidate: beyond this many, a candidate is as bad as any.
const MOST_COUNTED: usize = 16;
/// Obstacle tests one figure's placement may make: past this, the remaining labels stay where
/// the figure asked (a figure with thousands of crowded labels is placed in bounded time).
const MAX_TESTS: u64 = 4_000_000;
/// How much nearer its own point than any other a label's box should be, as a ratio of
/// distances: a label half-way between two points reads as either's.
const CLEARLY_NEARER: f64 = 1.5;
/// Grid cell size for the obstacle index, in pixels.
const CELL: f64 = 24.0;

/// How the text is anchored at its `x`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Anchor {
    Start,
    Middle,
    End,
}

impl Anchor {
    pub(crate) fn svg(self) -> &'static str {
        match self {
            Anchor::Start => "start",
            Anchor::Middle => "middle",
            Anchor::End => "end",
        }
    }
}

/// A label to place: its anchor point in pixels, the offset the figure asked for, its text.
pub(crate) struct Wanted<'a> {
    pub at: [f64; 2],
    pub dx: f64,
    pub dy: f64,
    pub text: &'a str,
}

/// Where a label is written: the text position (`x`, baseline `y`) and its anchoring.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Placed {
    pub x: f64,
    pub y: f64,
    pub anchor: Anchor,
}

/// The estimated box `[left, top, right, bottom]` of `text` written at `(x, y)`.
pub(crate) fn label_box(text: &str, x: f64, y: f64, anchor: Anchor) -> [f64; 4] {
    label_box_at(LABEL_FONT, text, x, y, anchor)
}

/// [`label_box`] at `font` pixels.
fn label_box_at(font: f64, text: &str, x: f64, y: f64, anchor: Anchor) -> [f64; 4] {
    let w = text.chars().count() as f64 * CHAR_EM * font;
    let left = match anchor {
        Anchor::Start => x,
        Anchor::Middle => x - w / 2.0,
        Anchor::End => x - w,
    };
    [left, y - ASCENT_EM * font, left + w, y + DESCENT_EM * font]
}

/// What labels must avoid, indexed by grid cell over the frame (cells outside it are
/// clamped to its border cells, which only makes those cells fuller).
pub(crate) struct Obstacles {
    segments: Vec<[f64; 4]>,
    dots: Vec<([f64; 2], f64)>,
    boxes: Vec<[f64; 4]>,
    frame: [f64; 4],
    origin: [f64; 2],
    columns: usize,
    rows: usize,
    cells: Vec<Vec<Obstacle>>,
    tests: std::cell::Cell<u64>,
}

#[derive(Clone, Copy, PartialEq)]
enum Obstacle {
    Segment(usize),
    Dot(usize),
    Box(usize),
}

impl Obstacles {
    /// No obstacles yet, in a frame `[left, top, right, bottom]`.
    pub(crate) fn new(frame: [f64; 4]) -> Self {
        let count = |span: f64| ((span / CELL).ceil().clamp(1.0, 4096.0)) as usize;
        let (columns, rows) = (count(frame[2] - frame[0]), count(frame[3] - frame[1]));
        Obstacles {
            segments: Vec::new(),
            dots: Vec::new(),
            boxes: Vec::new(),
            frame,
            origin: [frame[0], frame[1]],
            columns,
            rows,
            cells: vec![Vec::new(); columns * rows],
            tests: std::cell::Cell::new(0),
        }
    }

    /// The cells' column and row ranges a box covers.
    fn span(&self, b: [f64; 4]) -> Option<(std::ops::RangeInclusive<usize>, std::ops::RangeInclusive<usize>)> {
        if !b.iter().all(|v| v.is_finite()) {
            return None;
        }
        let at = |v: f64, o: f64, n: usize| ((v - o) / CELL).floor().clamp(0.0, (n - 1) as f64) as usize;
        Some((
            at(b[0], self.origin[0], self.columns)..=at(b[2], self.origin[0], self.columns),
            at(b[1], self.origin[1], self.rows)..=at(b[3], self.origin[1], self.rows),
        ))
    }

    fn index(&mut self, bounds: [f64; 4], o: Obstacle) {
        if let Some((xs, ys)) = self.span(bounds) {
            for j in ys {
                for i in xs.clone() {
                    self.cells[j * self.columns + i].push(o);
                }
            }
        }
    }

    /// A drawn straight segment (curves are added as their flattening).
    pub(crate) fn segment(&mut self, a: [f64; 2], b: [f64; 2]) {
        let bounds = [a[0].min(b[0]), a[1].min(b[1]), a[0].max(b[0]), a[1].max(b[1])];
        // a segment longer than many cells is split, so the grid stays a fine index
        let steps = (((b[0] - a[0]).abs().max((b[1] - a[1]).abs()) / (4.0 * CELL)).ceil() as usize).clamp(1, 1000);
        if steps > 1 {
            let at = |k: usize| {
                let s = k as f64 / steps as f64;
                [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])]
            };
            for k in 0..steps {
                self.segment(at(k), at(k + 1));
            }
            return;
        }
        self.segments.push([a[0], a[1], b[0], b[1]]);
        self.index(bounds, Obstacle::Segment(self.segments.len() - 1));
    }

    /// A point marker of radius `r`.
    pub(crate) fn dot(&mut self, at: [f64; 2], r: f64) {
        self.dots.push((at, r));
        self.index(
            [at[0] - r, at[1] - r, at[0] + r, at[1] + r],
            Obstacle::Dot(self.dots.len() - 1),
        );
    }

    /// A box to keep clear of (a placed label, a heading).
    pub(crate) fn boxed(&mut self, b: [f64; 4]) {
        self.boxes.push(b);
        self.index(b, Obstacle::Box(self.boxes.len() - 1));
    }

    /// How many obstacles the box (grown by [`GAP`]) touches, counting no further than `limit`.
    fn hits(&self, b: [f64; 4], limit: usize) -> usize {
        let g = [b[0] - GAP, b[1] - GAP, b[2] + GAP, b[3] + GAP];
        let Some((xs, ys)) = self.span(g) else {
            return limit;
        };
        let mut seen: Vec<Obstacle> = Vec::new();
        for j in ys {
            for i in xs.clone() {
                let cell = &self.cells[j * self.columns + i];
                self.tests.set(self.tests.get() + cell.len() as u64);
                for &o in cell {
                    let hit = match o {
                        Obstacle::Segment(k) => segment_meets_box(self.segments[k], g),
                        Obstacle::Dot(k) => dot_meets_box(self.dots[k], g),
                        Obstacle::Box(k) => boxes_meet(self.boxes[k], g),
                    };
                    if hit && !seen.contains(&o) {
                        seen.push(o);
                        if seen.len() >= limit {
                            return limit;
                        }
                    }
                }
            }
        }
        seen.len()
    }

    /// Whether some point marker other than the anchor's own lies about as near the box as
    /// the anchor, or nearer (within [`CLEARLY_NEARER`] times its distance): a reader might
    /// take the label for that point's.
    fn nearer_another_point(&self, b: [f64; 4], anchor: [f64; 2]) -> bool {
        let own = CLEARLY_NEARER * distance_to_box(anchor, b);
        let g = [b[0] - own, b[1] - own, b[2] + own, b[3] + own];
        let Some((xs, ys)) = self.span(g) else {
            return false;
        };
        for j in ys {
            for i in xs.clone() {
                let cell = &self.cells[j * self.columns + i];
                self.tests.set(self.tests.get() + cell.len() as u64);
                for &o in cell {
                    if let Obstacle::Dot(k) = o {
                        let (c, r) = self.dots[k];
                        let from_anchor = (c[0] - anchor[0]).hypot(c[1] - anchor[1]);
                        if from_anchor > r + 0.5 && distance_to_box(c, b) < own {
                            return true;
                        }
                    }
                }
            }
        }
        false
    }

    /// The candidate touching fewest things with the label at `font` pixels (the first free
    /// one), its cost and box.
    fn best_position(&self, l: &Wanted, font: f64, frame: [f64; 4]) -> (usize, Placed, [f64; 4]) {
        let mut best: Option<(usize, Placed, [f64; 4])> = None;
        let candidates = candidates(l, font);
        let tried = if self.tests.get() > MAX_TESTS {
            1
        } else {
            candidates.len()
        };
        for c in candidates.into_iter().take(tried) {
            let b = label_box_at(font, l.text, c.x, c.y, c.anchor);
            let outside = b[0] < frame[0] || b[1] < frame[1] || b[2] > frame[2] || b[3] > frame[3];
            let penalty = if outside { OUTSIDE } else { 0 };
            let least = best.as_ref().map_or(usize::MAX, |(least, _, _)| *least);
            if penalty >= least {
                continue;
            }
            // each obstacle counts twice, so that a free box nearer another point than its
            // own (a label read as that point's) loses only to a free box that is not
            let hits = self.hits(b, ((least - penalty) / 2 + 1).min(MOST_COUNTED));
            let cost = penalty + 2 * hits + usize::from(self.nearer_another_point(b, l.at));
            if cost >= least {
                continue;
            }
            if best.as_ref().is_none_or(|(least, _, _)| cost < *least) {
                best = Some((cost, c, b));
            }
            if cost == 0 {
                break;
            }
        }
        best.expect("at least one candidate")
    }

    /// Places the labels in order, each avoiding what is drawn and the labels before it, and
    /// keeping inside `frame` (`[left, top, right, bottom]`) when it can.
    pub(crate) fn place(&mut self, labels: &[Wanted]) -> Vec<Placed> {
        let frame = self.frame;
        labels
            .iter()
            .map(|l| {
                let (cost, mut placed, mut b) = self.best_position(l, LABEL_FONT, frame);
                if cost > 1 {
                    // crowded at the print size: a position free at the drawn size, if any
                    let (screen_cost, p, screen_box) = self.best_position(l, SVG_LABEL_FONT, frame);
                    if screen_cost <= 1 {
                        (placed, b) = (p, screen_box);
                    }
                }
                self.boxed(b);
                placed
            })
            .collect()
    }
}

/// The positions tried for a label, the one asked for first, then twelve directions around
/// the anchor at each of [`RADII`]: the box lies beyond the distance in that direction.
fn candidates(l: &Wanted, font: f64) -> Vec<Placed> {
    let [x, y] = l.at;
    let w = l.text.chars().count() as f64 * CHAR_EM * font;
    let h = (ASCENT_EM + DESCENT_EM) * font;
    let asked = Placed {
        x: x + l.dx,
        y: y + l.dy,
        anchor: if l.dx < 0.0 { Anchor::End } else { Anchor::Start },
    };
    let mut out = vec![asked];
    for r in RADII {
        for k in 0..12 {
            let angle = k as f64 * std::f64::consts::PI / 6.0;
            let (ux, uy) = (angle.cos(), -angle.sin());
            let left = x + r * ux + (ux - 1.0) * w / 2.0;
            let top = y + r * uy + (uy - 1.0) * h / 2.0;
            let (tx, anchor) = if ux > 0.3 {
                (left, Anchor::Start)
            } else if ux < -0.3 {
                (left + w, Anchor::End)
            } else {
                (left + w / 2.0, Anchor::Middle)
            };
            out.push(Placed {
                x: tx,
                y: top + ASCENT_EM * font,
                anchor,
            });
        }
    }
    out
}

/// The distance from `p` to the box (0 inside it).
fn distance_to_box(p: [f64; 2], b: [f64; 4]) -> f64 {
    let dx = p[0] - p[0].clamp(b[0], b[2]);
    let dy = p[1] - p[1].clamp(b[1], b[3]);
    dx.hypot(dy)
}

fn boxes_meet(a: [f64; 4], b: [f64; 4]) -> bool {
    a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3]
}

fn dot_meets_box((c, r): ([f64; 2], f64), b: [f64; 4]) -> bool {
    let dx = c[0] - c[0].clamp(b[0], b[2]);
    let dy = c[1] - c[1].clamp(b[1], b[3]);
    dx * dx + dy * dy <= r * r
}

/// Whether the segment `[x0, y0, x1, y1]` meets the box (Liang–Barsky clipping).
pub(crate) fn segment_meets_box(s: [f64; 4], b: [f64; 4]) -> bool {
    let (dx, dy) = (s[2] - s[0], s[3] - s[1]);
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, s[0] - b[0]),
        (dx, b[2] - s[0]),
        (-dy, s[1] - b[1]),
        (dy, b[3] - s[1]),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                lo = lo.max(r);
            } else {
                hi = hi.min(r);
            }
            if lo > hi {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segments_meet_boxes_they_cross_only() {
        let b = [0.0, 0.0, 10.0, 10.0];
        assert!(segment_meets_box([-5.0, 5.0, 15.0, 5.0], b));
        assert!(segment_meets_box([5.0, 5.0, 6.0, 6.0], b));
        assert!(!segment_meets_box([-5.0, -1.0, 15.0, -1.0], b));
        assert!(!segment_meets_box([11.0, 0.0, 20.0, 10.0], b));
        assert!(segment_meets_box([-5.0, 5.0, 5.0, 15.0], b));
        assert!(!segment_meets_box([-5.0, 6.0, 3.0, 15.0], b));
    }

    #[test]
    fn a_label_moves_off_a_line_through_its_asked_place() {
        let mut o = Obstacles::new([0.0, 0.0, 400.0, 400.0]);
        // a horizontal line right through where the label asks to be
        o.segment([0.0, 100.0], [400.0, 100.0]);
        let wanted = Wanted {
            at: [200.0, 100.0],
            dx: 6.0,
            dy: 4.0,
            text: "w₁ = 1/2",
        };
        let placed = o.place(&[wanted]);
        let b = label_box("w₁ = 1/2", placed[0].x, placed[0].y, placed[0].anchor);
        assert!(!segment_meets_box([0.0, 100.0, 400.0, 100.0], b), "{placed:?}");
        // a second label at the same anchor goes elsewhere
        let again = o.place(&[Wanted {
            at: [200.0, 100.0],
            dx: 6.0,
            dy: 4.0,
            text: "w₁ = 1/2",
        }]);
        let b2 = label_box("w₁ = 1/2", again[0].x, again[0].y, again[0].anchor);
        assert!(!boxes_meet(b, b2));
    }
}
