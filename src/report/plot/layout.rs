//! Where a history chart's annotations go (issue 40.7): each peak label in
//! free space beside its ring — clear of every drawn line, every ring, the
//! markers' labels and the labels placed before it — and the legend where
//! it covers no line, label or marker, or outside the plotting area when
//! there is no such place. Everything here is in image pixels.

/// A rectangle of pixels in image coordinates: columns `left..right`, rows
/// `top..bottom` (ends excluded).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct PixelBox {
    /// First column.
    pub left: i32,
    /// First row.
    pub top: i32,
    /// One past the last column.
    pub right: i32,
    /// One past the last row.
    pub bottom: i32,
}

impl PixelBox {
    /// The box of a drawing area's pixel ranges (as plotters'
    /// `get_pixel_range` gives them: columns, rows).
    pub fn of_ranges((columns, rows): (std::ops::Range<i32>, std::ops::Range<i32>)) -> Self {
        PixelBox {
            left: columns.start,
            top: rows.start,
            right: columns.end,
            bottom: rows.end,
        }
    }

    /// Whether the two rectangles share a pixel.
    pub fn intersects(&self, other: &PixelBox) -> bool {
        self.left < other.right
            && other.left < self.right
            && self.top < other.bottom
            && other.top < self.bottom
    }

    /// Whether `other` lies inside this one.
    pub fn contains(&self, other: &PixelBox) -> bool {
        other.left >= self.left
            && other.right <= self.right
            && other.top >= self.top
            && other.bottom <= self.bottom
    }

    /// Grown by `d` pixels on every side.
    pub(super) fn grown(&self, d: i32) -> PixelBox {
        PixelBox {
            left: self.left - d,
            top: self.top - d,
            right: self.right + d,
            bottom: self.bottom + d,
        }
    }

    /// Distance in pixels from `p` to the nearest pixel of the rectangle.
    pub(super) fn distance_to(&self, p: (i32, i32)) -> f64 {
        let dx = (self.left - p.0).max(p.0 - (self.right - 1)).max(0);
        let dy = (self.top - p.1).max(p.1 - (self.bottom - 1)).max(0);
        f64::from(dx).hypot(f64::from(dy))
    }

    /// The point of the rectangle nearest to `p`.
    pub(super) fn nearest_to(&self, p: (i32, i32)) -> (i32, i32) {
        (
            p.0.clamp(self.left, self.right - 1),
            p.1.clamp(self.top, self.bottom - 1),
        )
    }
}

/// Pixels of the plotting area taken by the drawing (lines, rings), with a
/// summed-area table: whether a rectangle is free in O(1).
pub(super) struct Occupancy {
    area: PixelBox,
    width: usize,
    taken: Vec<bool>,
    /// `sums[(r) * (width + 1) + c]`: taken pixels above row r, left of column c.
    sums: Vec<u32>,
}

impl Occupancy {
    pub(super) fn new(area: PixelBox) -> Self {
        let width = (area.right - area.left).max(0) as usize;
        let height = (area.bottom - area.top).max(0) as usize;
        Occupancy {
            area,
            width,
            taken: vec![false; width * height],
            sums: Vec::new(),
        }
    }

    fn mark_square(&mut self, (x, y): (i32, i32), r: i32) {
        let height = self.taken.len() / self.width.max(1);
        for row in (y - r)..=(y + r) {
            let row = row - self.area.top;
            if row < 0 || row as usize >= height {
                continue;
            }
            for col in (x - r)..=(x + r) {
                let col = col - self.area.left;
                if col >= 0 && (col as usize) < self.width {
                    self.taken[row as usize * self.width + col as usize] = true;
                }
            }
        }
    }

    /// A polyline of `half` pixels either side of its path.
    pub(super) fn mark_polyline(&mut self, points: &[(i32, i32)], half: i32) {
        if let [p] = points {
            self.mark_square(*p, half);
        }
        for pair in points.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let steps = (b.0 - a.0).abs().max((b.1 - a.1).abs()).max(1);
            for k in 0..=steps {
                let t = f64::from(k) / f64::from(steps);
                let p = (
                    a.0 + (f64::from(b.0 - a.0) * t).round() as i32,
                    a.1 + (f64::from(b.1 - a.1) * t).round() as i32,
                );
                self.mark_square(p, half);
            }
        }
    }

    /// A filled rectangle.
    pub(super) fn mark_box(&mut self, b: &PixelBox) {
        for row in b.top.max(self.area.top)..b.bottom.min(self.area.bottom) {
            for col in b.left.max(self.area.left)..b.right.min(self.area.right) {
                let (r, c) = (
                    (row - self.area.top) as usize,
                    (col - self.area.left) as usize,
                );
                self.taken[r * self.width + c] = true;
            }
        }
    }

    /// Builds the summed-area table: call after marking, before [`Self::free`].
    pub(super) fn seal(&mut self) {
        let w = self.width;
        let h = self.taken.len() / w.max(1);
        let mut sums = vec![0u32; (w + 1) * (h + 1)];
        for r in 0..h {
            let mut row_sum = 0u32;
            for c in 0..w {
                row_sum += u32::from(self.taken[r * w + c]);
                sums[(r + 1) * (w + 1) + c + 1] = sums[r * (w + 1) + c + 1] + row_sum;
            }
        }
        self.sums = sums;
    }

    /// Whether no pixel of `b` is taken; a rectangle reaching out of the
    /// area is not free.
    pub(super) fn free(&self, b: &PixelBox) -> bool {
        if !self.area.contains(b) || b.right <= b.left || b.bottom <= b.top {
            return false;
        }
        let w1 = self.width + 1;
        let (l, r) = (
            (b.left - self.area.left) as usize,
            (b.right - self.area.left) as usize,
        );
        let (t, u) = (
            (b.top - self.area.top) as usize,
            (b.bottom - self.area.top) as usize,
        );
        let s = |row: usize, col: usize| i64::from(self.sums[row * w1 + col]);
        s(u, r) - s(t, r) - s(u, l) + s(t, l) == 0
    }
}

/// Half-width of the band kept clear around a drawn line, pixels: the
/// 2-pixel stroke, its anti-aliased edge and a pixel of air.
pub(super) const LINE_CLEARANCE: i32 = 3;
/// Half-width of the square kept clear around a peak's ring (radius 5,
/// stroke 2).
pub(super) const RING_CLEARANCE: i32 = 8;
/// Pixels kept between two peak labels: two labels on one line must not
/// read as one.
const LABEL_GAP: i32 = 8;
/// A label farther than this from its ring (pixels) goes into the legend
/// instead: a long leader line across the panel reads worse.
const MAX_LABEL_DISTANCE: f64 = 170.0;
/// A label farther than this from its ring gets a leader line to it.
pub(super) const LEADER_DISTANCE: f64 = 14.0;

/// The free place nearest to the ring at `ring` for a `w × h` label:
/// above a maximum and below a minimum where there is room (`upward`),
/// off the marker lines at `markers` (columns) where it can be; none
/// within [`MAX_LABEL_DISTANCE`].
pub(super) fn place_label(
    occupancy: &Occupancy,
    placed: &[PixelBox],
    markers: &[i32],
    ring: (i32, i32),
    (w, h): (i32, i32),
    upward: bool,
) -> Option<PixelBox> {
    let area = occupancy.area;
    let mut best: Option<(f64, PixelBox)> = None;
    let mut top = area.top + 1;
    while top + h < area.bottom {
        let mut left = area.left + 1;
        while left + w < area.right {
            let b = PixelBox {
                left,
                top,
                right: left + w,
                bottom: top + h,
            };
            left += 2;
            let distance = b.distance_to(ring);
            if distance > MAX_LABEL_DISTANCE || best.is_some_and(|(c, _)| distance >= c) {
                continue;
            }
            // The side away from the line (above a maximum) reads as
            // belonging to the peak; a marker line through the text is a
            // smaller blemish than a long way to the label.
            let wrong_side = if upward {
                b.bottom > ring.1
            } else {
                b.top < ring.1
            };
            let crosses_marker = markers.iter().any(|&x| x >= b.left - 1 && x <= b.right);
            let cost = distance
                + if wrong_side { 10.0 } else { 0.0 }
                + if crosses_marker { 30.0 } else { 0.0 };
            if best.is_some_and(|(c, _)| cost >= c) {
                continue;
            }
            if occupancy.free(&b) && !placed.iter().any(|p| p.grown(LABEL_GAP).intersects(&b)) {
                best = Some((cost, b));
            }
        }
        top += 2;
    }
    best.filter(|(c, _)| *c <= MAX_LABEL_DISTANCE + 40.0)
        .map(|(_, b)| b)
}

/// A place inside the area for a `w × h` legend that covers no taken
/// pixel, no box of `avoid` and no marker column: the upper right, upper
/// left, lower right or lower left corner (5 px in) if one is free, else
/// the free place nearest a corner; none if there is no free place.
pub(super) fn place_legend(
    occupancy: &Occupancy,
    avoid: &[PixelBox],
    markers: &[i32],
    (w, h): (i32, i32),
) -> Option<PixelBox> {
    let area = occupancy.area;
    let at = |left: i32, top: i32| PixelBox {
        left,
        top,
        right: left + w,
        bottom: top + h,
    };
    let free = |b: &PixelBox| {
        occupancy.free(b)
            && !avoid.iter().any(|a| a.grown(2).intersects(b))
            && !markers.iter().any(|&x| x >= b.left - 2 && x <= b.right + 1)
    };
    let (l, r) = (area.left + 5, area.right - 5 - w);
    let (t, b) = (area.top + 5, area.bottom - 5 - h);
    if let Some(corner) = [at(r, t), at(l, t), at(r, b), at(l, b)]
        .into_iter()
        .find(|c| free(c))
    {
        return Some(corner);
    }
    let corners = [(r, t), (l, t), (r, b), (l, b)];
    let mut best: Option<(i32, PixelBox)> = None;
    let mut top = t;
    while top <= b {
        let mut left = l;
        while left <= r {
            let c = at(left, top);
            let d = corners
                .iter()
                .map(|&(x, y)| (x - left).abs() + (y - top).abs())
                .min()
                .unwrap_or(0);
            if best.is_none_or(|(bd, _)| d < bd) && free(&c) {
                best = Some((d, c));
            }
            left += 3;
        }
        top += 3;
    }
    best.map(|(_, c)| c)
}
