//! The AASHTO standard trucks as axle loads: H20-44 and HS20-44.
//!
//! AASHTO Standard Specifications for Highway Bridges, 17th ed. (2002),
//! Article 3.7 (highway loads): the H20-44 truck (Art. 3.7.6, Fig. 3.7.6A,
//! "Standard H trucks") has a front axle of 0.2 W = 8 000 lb and a rear axle
//! of 0.8 W = 32 000 lb at 14 ft, W = 40 000 lb (20 short tons); the HS20-44
//! truck (Art. 3.7.7, Fig. 3.7.7A, "Standard HS trucks") adds a semitrailer
//! axle of 32 000 lb at a variable spacing V of 14 ft to 30 ft behind the
//! rear tractor axle ("the spacing to be used is that which produces
//! maximum stresses"). The wheels of an axle are 6 ft apart, each carrying
//! half the axle load. The AASHTO LRFD Bridge Design Specifications keep the
//! HS20-44 axles as the design truck of the HL-93 load (Art. 3.6.1.2.2,
//! Fig. 3.6.1.2.2-1: 8.0 kip, 32.0 kip, 32.0 kip; 14 ft, 14–30 ft; 6 ft
//! between the wheels), which its SI editions round to 35 kN, 145 kN,
//! 145 kN, 4.3 m and 4.3–9.0 m.
//!
//! The values here are the customary ones converted exactly (1 lbf =
//! 4.448 221 615 260 5 N, 1 ft = 0.3048 m): 35.586 kN and 142.343 kN,
//! 4.2672 m and 9.144 m. They are design loads: constant forces without a
//! vehicle's mass or suspension (no inertia), as the specifications define
//! them. The plate paper's 7-DOF truck (`type: h20_44`) borrows the H20-44
//! geometry but not these loads (its static wheel forces are 58.81 kN front
//! and 32.42 kN rear, [`super::H20Truck`]).

/// One kip (1 000 lbf), N: the pound-force is 0.453 592 37 kg × 9.806 65 m/s²
/// exactly.
pub const KIP: f64 = 4_448.221_615_260_5;
/// One foot, m (exact).
pub const FOOT: f64 = 0.3048;

/// H20-44 (AASHTO Standard Specifications, 17th ed., Fig. 3.7.6A): axle
/// loads front first, N (8 and 32 kip).
pub const H20_44_AXLE_LOADS: [f64; 2] = [8.0 * KIP, 32.0 * KIP];
/// H20-44: front to rear axle, m (14 ft).
pub const H20_44_AXLE_SPACING: f64 = 14.0 * FOOT;

/// HS20-44 (AASHTO Standard Specifications, 17th ed., Fig. 3.7.7A; the LRFD
/// design truck of Art. 3.6.1.2.2): axle loads front first, N (8, 32 and
/// 32 kip).
pub const HS20_44_AXLE_LOADS: [f64; 3] = [8.0 * KIP, 32.0 * KIP, 32.0 * KIP];
/// HS20-44: front to rear tractor axle, m (14 ft).
pub const HS20_44_FRONT_SPACING: f64 = 14.0 * FOOT;
/// HS20-44: the shortest rear spacing V (rear tractor axle to semitrailer
/// axle), m (14 ft); the default, the spacing LRFD 3.6.1.2.2 takes for the
/// design truck unless a longer one governs.
pub const HS20_44_REAR_SPACING_MIN: f64 = 14.0 * FOOT;
/// HS20-44: the longest rear spacing V, m (30 ft).
pub const HS20_44_REAR_SPACING_MAX: f64 = 30.0 * FOOT;
/// Both trucks: the distance between the two wheels of an axle, m (6 ft).
/// The axle loads act on the vehicle's path (`lateral_position`); to load
/// a plate deck wheel by wheel, give two moving forces this far apart with
/// half the axle loads.
pub const WHEEL_SPACING: f64 = 6.0 * FOOT;

/// The HS20-44's axle spacings for a rear spacing `rear`, m.
pub fn hs20_44_spacings(rear: f64) -> [f64; 2] {
    [HS20_44_FRONT_SPACING, rear]
}
