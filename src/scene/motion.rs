//! How a vehicle travels along the bridge: a speed at t = 0 and a constant
//! acceleration, with the front axle reaching the entrance x = 0 at the
//! entry time. A braking vehicle (negative acceleration) that comes to a
//! stop stays where it stopped: it never reverses.
//!
//! Kinematics of constant acceleration a from the speed v₀ at t = 0
//! (elementary; e.g. Meriam & Kraige, Dynamics, §2/2):
//! v(t) = v₀ + a t,  x(t) = x₀ + v₀ t + ½ a t²,
//! written here relative to the entry time t_e (x(t_e) = 0) as
//! x(t) = (t − t_e)·(v₀ + ½ a (t + t_e)), so the entry is exact. With a = 0
//! the position is computed as v₀ (t − t_e), the constant-speed formula,
//! so a scene without acceleration runs bit for bit as before.

/// A vehicle's motion along its path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
    /// Speed at t = 0, m/s (> 0).
    pub speed: f64,
    /// Constant acceleration, m/s² (negative: braking); 0 for constant speed.
    pub acceleration: f64,
    /// Time at which the front axle reaches x = 0, s.
    pub entry_time: f64,
}

impl Motion {
    /// The time the vehicle stops (braking only), s; `None` if it never does.
    #[inline]
    pub fn stop_time(&self) -> Option<f64> {
        (self.acceleration < 0.0).then(|| -self.speed / self.acceleration)
    }

    /// `t` clamped to the stop time: after it nothing moves.
    #[inline]
    fn moving_time(&self, t: f64) -> f64 {
        match self.stop_time() {
            Some(stop) if t > stop => stop,
            _ => t,
        }
    }

    /// Front-axle position at time `t`, m.
    #[inline]
    pub fn position(&self, t: f64) -> f64 {
        if self.acceleration == 0.0 {
            return self.speed * (t - self.entry_time);
        }
        let t = self.moving_time(t);
        (t - self.entry_time) * (self.speed + 0.5 * self.acceleration * (t + self.entry_time))
    }

    /// Speed at time `t`, m/s (0 once stopped).
    #[inline]
    pub fn speed_at(&self, t: f64) -> f64 {
        if self.acceleration == 0.0 {
            return self.speed;
        }
        (self.speed + self.acceleration * t).max(0.0)
    }

    /// Acceleration at time `t`, m/s² (0 once stopped).
    #[inline]
    pub fn acceleration_at(&self, t: f64) -> f64 {
        match self.stop_time() {
            Some(stop) if t >= stop => 0.0,
            _ => self.acceleration,
        }
    }

    /// The first time at or after 0 the front axle reaches `x` (m), or
    /// `None` if it stops before. `x` at or behind the start gives 0 or less.
    pub fn time_at(&self, x: f64) -> Option<f64> {
        // Distance to go from the position at t = 0.
        let start = self.position(0.0);
        let distance = x - start;
        if distance <= 0.0 {
            return Some(distance / self.speed.max(f64::MIN_POSITIVE));
        }
        time_to_cover(self.speed, self.acceleration, distance)
    }

    /// The largest speed reached up to time `t`, m/s.
    pub fn top_speed(&self, t: f64) -> f64 {
        self.speed.max(self.speed_at(t.max(0.0)))
    }
}

/// The time to cover `distance` ≥ 0 (m) from speed `speed` (m/s) with
/// constant acceleration `acceleration` (m/s²), or `None` if a braking
/// vehicle stops first. The root of ½ a t² + v t − d = 0 in the form
/// t = 2d / (v + √(v² + 2ad)), free of cancellation for either sign of a.
pub fn time_to_cover(speed: f64, acceleration: f64, distance: f64) -> Option<f64> {
    if acceleration == 0.0 {
        return (speed > 0.0).then(|| distance / speed);
    }
    let discriminant = speed * speed + 2.0 * acceleration * distance;
    if discriminant < 0.0 {
        return None;
    }
    let denominator = speed + discriminant.sqrt();
    if denominator <= 0.0 {
        return (distance == 0.0).then_some(0.0);
    }
    Some(2.0 * distance / denominator)
}

/// The scene's vehicle in motion: its kinematics live here, with [`Motion`],
/// so the scene description stays plain data.
impl crate::scene::Vehicle {
    /// How the vehicle travels (speed at t = 0, acceleration, entry time).
    pub fn motion(&self) -> Motion {
        Motion {
            speed: self.speed(),
            acceleration: self.acceleration(),
            entry_time: self.entry_time(),
        }
    }

    /// Time at which the last axle leaves a bridge of length `length` (m), s;
    /// for a vehicle that brakes to a stop before, the time it stops.
    pub fn exit_time(&self, length: f64) -> f64 {
        if self.acceleration() == 0.0 {
            return self.entry_time() + (length + self.length()) / self.speed();
        }
        let motion = self.motion();
        motion
            .time_at(length + self.length())
            .or(motion.stop_time())
            .unwrap_or(f64::INFINITY)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constant_acceleration_kinematics() {
        // v₀ = 10 m/s, a = 2 m/s², entering at t = 1 s: x(t) = −11 + 10t + t².
        let m = Motion {
            speed: 10.0,
            acceleration: 2.0,
            entry_time: 1.0,
        };
        assert_eq!(m.position(1.0), 0.0);
        assert!((m.position(3.0) - (-11.0 + 30.0 + 9.0)).abs() < 1e-12);
        assert_eq!(m.speed_at(3.0), 16.0);
        assert_eq!(m.acceleration_at(3.0), 2.0);
        let t = m.time_at(28.0).unwrap();
        assert!((t - 3.0).abs() < 1e-12, "{t}");
    }

    #[test]
    fn braking_stops_and_stays() {
        // v₀ = 20 m/s, a = −4 m/s²: stops at t = 5 s after 50 m.
        let m = Motion {
            speed: 20.0,
            acceleration: -4.0,
            entry_time: 0.0,
        };
        assert_eq!(m.stop_time(), Some(5.0));
        assert!((m.position(5.0) - 50.0).abs() < 1e-12);
        assert_eq!(m.position(9.0), m.position(5.0));
        assert_eq!(m.speed_at(7.0), 0.0);
        assert_eq!(m.acceleration_at(7.0), 0.0);
        assert!(m.time_at(50.5).is_none());
        assert!((m.time_at(50.0).unwrap() - 5.0).abs() < 1e-6);
    }

    #[test]
    fn no_acceleration_is_the_constant_speed_formula() {
        let m = Motion {
            speed: 27.7,
            acceleration: 0.0,
            entry_time: 0.3,
        };
        for k in 0..100 {
            let t = k as f64 * 0.0137;
            assert_eq!(
                m.position(t).to_bits(),
                (27.7 * (t - 0.3)).to_bits(),
                "bit for bit"
            );
        }
    }
}
