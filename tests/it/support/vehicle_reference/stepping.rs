//! Stepping: RK4 at a fixed step, rigid-contact events located by
//! bisection, statistics and samples (see the parent module).
#![allow(clippy::needless_range_loop)]

use super::dynamics::{Layout, Work};
use super::{Case, History, Mode, WheelStatistics};

impl Case {
    /// One RK4 step of length `h` from (t, y) into `out`.
    #[allow(clippy::too_many_arguments)]
    fn rk4(
        &self,
        modes: &[Mode],
        layout: &Layout,
        t: f64,
        y: &[f64],
        h: f64,
        out: &mut [f64],
        scratch: &mut Scratch,
        work: &mut Work,
    ) {
        let dim = y.len();
        let stages = [(0.0, 0usize), (0.5, 0), (0.5, 1), (1.0, 2)];
        for (s, &(c, from)) in stages.iter().enumerate() {
            if s == 0 {
                scratch.yt.copy_from_slice(y);
            } else {
                for m in 0..dim {
                    scratch.yt[m] = y[m] + c * h * scratch.k[from][m];
                }
            }
            let (_, tail) = scratch.k.split_at_mut(s);
            self.rhs(
                modes,
                layout,
                t + c * h,
                &scratch.yt,
                &mut tail[0],
                &mut scratch.delta,
                &mut scratch.position,
                work,
            );
        }
        let k = &scratch.k;
        for m in 0..dim {
            out[m] = y[m] + h / 6.0 * (k[0][m] + 2.0 * k[1][m] + 2.0 * k[2][m] + k[3][m]);
        }
    }

    /// Contact forces (into `work.force`), compressions and positions at (t, y).
    #[allow(clippy::too_many_arguments)]
    fn evaluate(
        &self,
        modes: &[Mode],
        layout: &Layout,
        t: f64,
        y: &[f64],
        scratch: &mut Scratch,
        work: &mut Work,
    ) {
        let mut dy = std::mem::take(&mut scratch.dy);
        self.rhs(
            modes,
            layout,
            t,
            y,
            &mut dy,
            &mut scratch.delta,
            &mut scratch.position,
            work,
        );
        scratch.dy = dy;
    }

    /// The rigid-contact event of wheel `c` at the current evaluation: how
    /// far past it the state is (> 0: a held wheel's force below 0, or a
    /// free point below the surface, m or N).
    fn event(&self, c: usize, scratch: &Scratch, work: &Work) -> f64 {
        if work.in_contact[c] {
            -work.force[c]
        } else {
            // Below the surface by more than 10 fm (round-off of s).
            scratch.delta[c] - 1e-14
        }
    }

    /// Integrates [0, t_end] with RK4 at step `h` and samples at `times`
    /// (multiples of h within 0.5h).
    pub fn run(&self, times: &[f64], t_end: f64, h: f64) -> History {
        let modes = self.modes();
        let nm = modes.len();
        let layout = self.layout(nm);
        let dim = layout.dim;
        let mut y = vec![0.0; dim];
        for (v, vehicle) in self.vehicles.iter().enumerate() {
            assert!(vehicle.entry_time >= 0.0 && vehicle.speed > 0.0);
            let u = vehicle.static_state(|p| {
                if self.rigid {
                    0.0
                } else {
                    (p / self.contact_coefficient).powf(1.0 / self.contact_exponent)
                }
            });
            let b = layout.offsets[v];
            y[b..b + vehicle.dofs()].copy_from_slice(&u);
            for (i, &m) in vehicle.masses.iter().enumerate() {
                assert!(m > 0.0 || vehicle.own_damping(i) > 0.0);
            }
        }
        let nw: usize = self.vehicles.iter().map(|v| v.wheels.len()).sum();
        // Which coordinate of the state each wheel's point is.
        let wheel_dofs: Vec<usize> = self
            .vehicles
            .iter()
            .enumerate()
            .flat_map(|(v, vehicle)| vehicle.wheels.iter().map(move |w| (v, w.dof)))
            .map(|(v, dof)| layout.offsets[v] + dof)
            .collect();
        // Each wheel's mass (0: a massless point) and velocity coordinate.
        let wheel_masses: Vec<(f64, usize)> = self
            .vehicles
            .iter()
            .enumerate()
            .flat_map(|(v, vehicle)| {
                let base = layout.offsets[v] + vehicle.dofs();
                vehicle
                    .wheels
                    .iter()
                    .map(move |w| (vehicle.masses[w.dof], base + w.dof))
            })
            .collect();
        let steps = (t_end / h).round() as usize;
        let mut scratch = Scratch {
            k: vec![vec![0.0; dim]; 4],
            yt: vec![0.0; dim],
            dy: vec![0.0; dim],
            delta: vec![0.0; nw],
            position: vec![0.0; nw],
        };
        let top = modes.iter().map(|m| m.m.max(m.n)).max().unwrap_or(0) + 1;
        let mut work = Work {
            shape: vec![0.0; nm],
            under: vec![0.0; nw * nm],
            along: vec![0.0; top],
            across: vec![0.0; top],
            du: Vec::new(),
            contact: Vec::new(),
            q: Vec::new(),
            slope: vec![0.0; nm],
            curvature: vec![0.0; nm],
            surface_transport: vec![0.0; nw],
            along_cos: vec![0.0; top],
            surface_rate: vec![0.0; nw],
            force: vec![0.0; nw],
            in_contact: vec![true; nw],
            own_damping: self
                .vehicles
                .iter()
                .map(|v| (0..v.dofs()).map(|i| v.own_damping(i)).collect())
                .collect(),
        };
        let mut out = History {
            contact_force: vec![Vec::new(); nw],
            wheels: vec![WheelStatistics::default(); nw],
            ..Default::default()
        };
        let probe = self.probe;
        let probe_shape: Vec<f64> = modes
            .iter()
            .map(|mode| self.shape(mode, probe.0, probe.1))
            .collect();
        let sample = |y: &[f64], force: &[f64], out: &mut History| {
            out.deflection
                .push(probe_shape.iter().zip(y).map(|(p, q)| p * q).sum());
            for (c, f) in force.iter().enumerate() {
                out.contact_force[c].push(*f);
            }
        };
        self.evaluate(&modes, &layout, 0.0, &y, &mut scratch, &mut work);
        let mut next = 0usize;
        while next < times.len() && times[next] <= 0.5 * h {
            sample(&y, &work.force, &mut out);
            next += 1;
        }
        let mut previous = scratch.delta.clone();
        let mut previous_position = scratch.position.clone();
        let (mut y_end, mut y_try) = (vec![0.0; dim], vec![0.0; dim]);
        // The contact forces of the two previous grid points, per wheel.
        let mut recent: Vec<[f64; 2]> = work.force.iter().map(|&f| [f, f]).collect();
        for i in 0..steps {
            let t = i as f64 * h;
            let t1 = (i + 1) as f64 * h;
            if self.rigid {
                // Step to t1, stopping at every event on the way.
                let mut tc = t;
                loop {
                    let rest = t1 - tc;
                    self.rk4(
                        &modes,
                        &layout,
                        tc,
                        &y,
                        rest,
                        &mut y_end,
                        &mut scratch,
                        &mut work,
                    );
                    self.evaluate(&modes, &layout, t1, &y_end, &mut scratch, &mut work);
                    let crossed: Vec<usize> = (0..nw)
                        .filter(|&c| self.event(c, &scratch, &work) > 0.0)
                        .collect();
                    if crossed.is_empty() {
                        y.copy_from_slice(&y_end);
                        break;
                    }
                    // Earliest event: bisection on the step length.
                    let mut earliest = (rest, crossed[0]);
                    for &c in &crossed {
                        let (mut lo, mut hi) = (0.0, rest);
                        while hi - lo > 1e-15 {
                            let mid = 0.5 * (lo + hi);
                            self.rk4(
                                &modes,
                                &layout,
                                tc,
                                &y,
                                mid,
                                &mut y_try,
                                &mut scratch,
                                &mut work,
                            );
                            self.evaluate(
                                &modes,
                                &layout,
                                tc + mid,
                                &y_try,
                                &mut scratch,
                                &mut work,
                            );
                            if self.event(c, &scratch, &work) > 0.0 {
                                hi = mid;
                            } else {
                                lo = mid;
                            }
                        }
                        if hi < earliest.0 {
                            earliest = (hi, c);
                        }
                    }
                    let (tau, c) = earliest;
                    self.rk4(
                        &modes,
                        &layout,
                        tc,
                        &y,
                        tau,
                        &mut y_end,
                        &mut scratch,
                        &mut work,
                    );
                    y.copy_from_slice(&y_end);
                    tc += tau;
                    self.evaluate(&modes, &layout, tc, &y, &mut scratch, &mut work);
                    // The point is on the surface at the event: put it there
                    // exactly (removes the 1e-15 s of the bracket).
                    y[wheel_dofs[c]] += scratch.delta[c];
                    let w = &mut out.wheels[c];
                    if work.in_contact[c] {
                        w.losses += 1;
                        if w.first_loss.is_none() {
                            w.first_loss = Some((tc, scratch.position[c]));
                        }
                    } else {
                        out.first_landing.get_or_insert(tc);
                        let (m, velocity) = wheel_masses[c];
                        if m > 0.0 {
                            // A wheel with mass lands: a plastic impact on this
                            // wheel alone, Λ = −(u̇ − ṡ)/(1/m + Σφ²/M) up on the
                            // wheel and down on the deck. (With other wheels
                            // held on the deck a full impact would be a
                            // multi-contact problem: compare only up to
                            // `first_landing`.)
                            let under = &work.under[c * nm..(c + 1) * nm];
                            let relative = y[velocity] - work.surface_rate[c];
                            let deck: f64 =
                                modes.iter().zip(under).map(|(mo, p)| p * p / mo.mass).sum();
                            let impulse = -relative / (1.0 / m + deck);
                            y[velocity] += impulse / m;
                            for (j, mode) in modes.iter().enumerate() {
                                y[nm + j] -= impulse * under[j] / mode.mass;
                            }
                        }
                    }
                    work.in_contact[c] = !work.in_contact[c];
                    if t1 - tc <= 1e-15 {
                        break;
                    }
                }
                // Held points stay on the surface (RK4 drift, 1e-16 m), and
                // held wheels with mass move with it.
                self.evaluate(&modes, &layout, t1, &y, &mut scratch, &mut work);
                for c in 0..nw {
                    if work.in_contact[c] {
                        y[wheel_dofs[c]] += scratch.delta[c];
                        if wheel_masses[c].0 > 0.0 {
                            y[wheel_masses[c].1] = work.surface_rate[c];
                        }
                    }
                }
            } else {
                self.rk4(
                    &modes,
                    &layout,
                    t,
                    &y,
                    h,
                    &mut y_end,
                    &mut scratch,
                    &mut work,
                );
                y.copy_from_slice(&y_end);
            }
            self.evaluate(&modes, &layout, t1, &y, &mut scratch, &mut work);
            let (delta, pos) = (&scratch.delta, &scratch.position);
            for c in 0..nw {
                let w = &mut out.wheels[c];
                let d = delta[c];
                let f = work.force[c];
                w.max_force = w.max_force.max(f);
                // A smooth peak between grid points: the vertex of the
                // parabola through the last three values (O(h³) instead of
                // the grid's O(h²)), where the correction is small (not at a
                // rigid landing's jump).
                let [f0, f1] = recent[c];
                let bend = 2.0 * f1 - f0 - f;
                if f1 >= f0 && f1 >= f && bend > 0.0 {
                    let correction = (f0 - f) * (f0 - f) / (8.0 * bend);
                    if correction < 1e-4 * f1 {
                        w.max_force = w.max_force.max(f1 + correction);
                    }
                }
                recent[c] = [f1, f];
                w.max_gap = w.max_gap.max(-d);
                if -d > 1e-9 && w.first_nanometre.is_none() {
                    w.first_nanometre = Some(t1);
                }
                if !self.rigid && previous[c] > 0.0 && d <= 0.0 {
                    w.losses += 1;
                    if w.first_loss.is_none() {
                        let s = previous[c] / (previous[c] - d);
                        w.first_loss = Some((
                            t + s * h,
                            previous_position[c] + s * (pos[c] - previous_position[c]),
                        ));
                    }
                }
            }
            previous.copy_from_slice(delta);
            previous_position.copy_from_slice(pos);
            while next < times.len() && (times[next] - t1).abs() <= 0.5 * h {
                sample(&y, &work.force, &mut out);
                next += 1;
            }
        }
        assert_eq!(
            next,
            times.len(),
            "output times must be multiples of h in [0, t_end]"
        );
        out
    }
}

/// Scratch space of the stepping.
struct Scratch {
    k: Vec<Vec<f64>>,
    yt: Vec<f64>,
    dy: Vec<f64>,
    delta: Vec<f64>,
    position: Vec<f64>,
}
