//! The HSLM-A universal trains of EN 1991-2:2003 Annex E (high-speed load
//! model for the dynamic analysis of railway bridges, 6.4.6.1.1): ten
//! articulated trains of point axle forces.
//!
//! Table E.1 gives per train the number of intermediate coaches N, the coach
//! length D (m, between the centres of consecutive Jacobs bogies), the
//! bogie axle spacing d (m) and the point force P per axle (kN). Figure E.2
//! gives the layout, front to rear: a power car (axles at 0, 3, 14 and 17 m),
//! 3.525 m to the first axle of the end coach's own bogie (spacing d), then
//! N + 1 Jacobs bogies at D centre to centre, the first
//! D − (3.525 + d)/2 behind the end coach's bogie centre, and the same
//! end coach and power car mirrored at the rear: 2 × 4 + 2 × 2 + 2 (N + 1)
//! axles. The geometry was checked axle by axle against the HSLM tables
//! distributed with caldintav (Universidad Politécnica de Madrid), which
//! it reproduces to 1e-6 m for all ten trains (e.g. HSLM-A1: 50 axles, the
//! last at 397.525 m; HSLM-A10: 36 axles, the last at 388.525 m).

/// One row of EN 1991-2 Table E.1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HslmTrain {
    /// Number of intermediate coaches N.
    pub coaches: usize,
    /// Coach length D, m.
    pub coach_length: f64,
    /// Bogie axle spacing d, m.
    pub bogie_axle_spacing: f64,
    /// Point force per axle P, N.
    pub axle_force: f64,
}

/// EN 1991-2:2003 Table E.1, HSLM-A1 … HSLM-A10 (P converted from kN to N).
pub const HSLM_A: [HslmTrain; 10] = [
    train(18, 18.0, 2.0, 170.0),
    train(17, 19.0, 3.5, 200.0),
    train(16, 20.0, 2.0, 180.0),
    train(15, 21.0, 3.0, 190.0),
    train(14, 22.0, 2.0, 170.0),
    train(13, 23.0, 2.0, 180.0),
    train(13, 24.0, 2.0, 190.0),
    train(12, 25.0, 2.5, 190.0),
    train(11, 26.0, 2.0, 210.0),
    train(11, 27.0, 2.0, 210.0),
];

const fn train(coaches: usize, coach_length: f64, d: f64, kn: f64) -> HslmTrain {
    HslmTrain {
        coaches,
        coach_length,
        bogie_axle_spacing: d,
        axle_force: kn * 1000.0,
    }
}

/// Power car axles behind the front axle, m (Figure E.2).
const POWER_CAR: [f64; 4] = [0.0, 3.0, 14.0, 17.0];
/// Last power-car axle to the first end-coach axle, m (Figure E.2).
const POWER_TO_COACH: f64 = 3.525;

impl HslmTrain {
    /// Distance of every axle behind the front axle, m, front to rear.
    pub fn axle_positions(&self) -> Vec<f64> {
        let d = self.bogie_axle_spacing;
        let big_d = self.coach_length;
        let mut x: Vec<f64> = POWER_CAR.to_vec();
        let coach = POWER_CAR[3] + POWER_TO_COACH;
        x.extend([coach, coach + d]);
        let end_bogie = coach + 0.5 * d;
        let first_jacobs = end_bogie + big_d - 0.5 * (POWER_TO_COACH + d);
        for k in 0..=self.coaches {
            let centre = first_jacobs + k as f64 * big_d;
            x.extend([centre - 0.5 * d, centre + 0.5 * d]);
        }
        let last_jacobs = first_jacobs + self.coaches as f64 * big_d;
        let rear_bogie = last_jacobs + big_d - 0.5 * (POWER_TO_COACH + d);
        x.extend([rear_bogie - 0.5 * d, rear_bogie + 0.5 * d]);
        let power = rear_bogie + 0.5 * d + POWER_TO_COACH;
        x.extend(POWER_CAR.map(|p| power + p));
        x
    }

    /// Number of axles, 2 (N + 7).
    pub fn axle_count(&self) -> usize {
        2 * (self.coaches + 7)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The axle count 2 (N + 7) holds for every train and the positions
    /// increase.
    #[test]
    fn every_train_is_ordered_and_counted() {
        for train in HSLM_A {
            let x = train.axle_positions();
            assert_eq!(x.len(), train.axle_count());
            assert!(x.windows(2).all(|w| w[1] > w[0]));
        }
    }
}
