//! Power spectral densities of track and road irregularity.
//!
//! Convention used everywhere in vbi: a **one-sided** PSD G(Ω) in
//! m²/(rad/m) of the wavenumber Ω = 2π/λ in rad/m, so that the variance of
//! the profile over a band is σ² = ∫ G(Ω) dΩ over the band (Ω > 0 only).
//! Each source's own convention is converted in its function and said there.

use std::f64::consts::PI;

use crate::scene::{Interference, IsoClass, Spectrum};

/// One square centimetre in square metres: the FRA tables give A in
/// cm²·rad/m.
const CM2: f64 = 1e-4;

/// FRA scale factor k of the vertical and alignment spectra: 0.25, the
/// value the railway literature pairs with the FRA table (e.g. Zhai,
/// *Vehicle–Track Coupled Dynamics*, Ch. 2, and the LCP paper's ref. [33]).
pub const FRA_K: f64 = 0.25;

/// Ω_c of every FRA class, rad/m.
pub const FRA_CUTOFF: f64 = 0.8245;

/// The FRA track classes' parameters: (A_v, A_a) in cm²·rad/m and Ω_s in
/// rad/m, classes 1 to 6 (US Federal Railroad Administration track
/// geometry spectra, as tabulated in the railway literature, e.g. Zhai,
/// *Vehicle–Track Coupled Dynamics*, Ch. 2). Class 6 is the best track,
/// class 1 the worst.
pub const FRA_CLASSES: [(f64, f64, f64); 6] = [
    (1.2107, 3.3634, 0.6046),
    (1.0181, 1.2107, 0.9308),
    (0.6816, 0.4128, 0.8520),
    (0.5376, 0.3027, 1.1312),
    (0.2095, 0.0762, 0.8209),
    (0.0339, 0.0339, 0.4380),
];

/// One mile per hour in m/s (exact: 1609.344 m / 3600 s).
pub const MPH: f64 = 0.44704;

/// The maximum operating speeds the FRA track classes 1–6 are maintained
/// for, (freight, passenger) in mph: 49 CFR 213.9(a) for classes 1–5 (10/15,
/// 25/30, 40/60, 60/80, 80/90) and 49 CFR 213.307(a) for class 6 (110 mph,
/// every train). A track class's geometry limits, hence its spectrum, are
/// those of a line kept for these speeds; faster trains run on better track.
pub const FRA_MAX_SPEED_MPH: [(f64, f64); 6] = [
    (10.0, 15.0),
    (25.0, 30.0),
    (40.0, 60.0),
    (60.0, 80.0),
    (80.0, 90.0),
    (110.0, 110.0),
];

/// The highest speed any train may run on FRA track class `class` (1–6),
/// m/s: the passenger limit of [`FRA_MAX_SPEED_MPH`].
pub fn fra_max_speed(class: u8) -> f64 {
    FRA_MAX_SPEED_MPH[usize::from(class.clamp(1, 6)) - 1].1 * MPH
}

/// Vertical profile PSD of FRA track class `class` (1–6), m²/(rad/m),
/// one-sided, at wavenumber `omega` (rad/m):
/// G_v(Ω) = k A_v Ω_c² / (Ω² (Ω² + Ω_c²)), A_v from [`FRA_CLASSES`]
/// converted from cm²·rad/m to m²·rad/m, k = [`FRA_K`], Ω_c = [`FRA_CUTOFF`].
/// Valid per FRA for wavelengths of about 1.5–300 m.
pub fn fra_vertical(class: u8, omega: f64) -> f64 {
    let (a_v, _, _) = FRA_CLASSES[usize::from(class.clamp(1, 6)) - 1];
    fra_shape(a_v * CM2, omega)
}

/// Alignment (lateral) PSD of FRA track class `class` (1–6), m²/(rad/m),
/// one-sided: G_a(Ω) = k A_a Ω_c² / (Ω² (Ω² + Ω_c²)) (for the 3D train).
pub fn fra_alignment(class: u8, omega: f64) -> f64 {
    let (_, a_a, _) = FRA_CLASSES[usize::from(class.clamp(1, 6)) - 1];
    fra_shape(a_a * CM2, omega)
}

fn fra_shape(a: f64, omega: f64) -> f64 {
    let wc2 = FRA_CUTOFF * FRA_CUTOFF;
    FRA_K * a * wc2 / (omega * omega * (omega * omega + wc2))
}

/// German high-speed track spectra (ORE B176 / DB): Ω_c, rad/m.
pub const GERMAN_CUTOFF: f64 = 0.8246;
/// German high-speed spectra: Ω_r, rad/m.
pub const GERMAN_ROLL_OFF: f64 = 0.0206;

impl Interference {
    /// (A_v, A_a), m²·rad/m.
    fn coefficients(self) -> (f64, f64) {
        match self {
            Interference::Low => (4.032e-7, 2.119e-7),
            Interference::High => (1.080e-6, 6.125e-7),
        }
    }
}

/// Vertical profile PSD of the German high-speed spectrum, m²/(rad/m),
/// one-sided: G_v(Ω) = A_v Ω_c² / ((Ω² + Ω_r²)(Ω² + Ω_c²)), Ω_c = 0.8246,
/// Ω_r = 0.0206 rad/m, A_v per [`Interference`] (the spectra of German
/// high-speed lines as tabulated in the railway literature, e.g. Zhai's
/// book, Ch. 2). Units: A in m²·rad/m, Ω in rad/m.
pub fn german_vertical(level: Interference, omega: f64) -> f64 {
    german_shape(level.coefficients().0, omega)
}

/// Alignment PSD of the German high-speed spectrum, m²/(rad/m), one-sided:
/// the vertical form with A_a in place of A_v.
pub fn german_alignment(level: Interference, omega: f64) -> f64 {
    german_shape(level.coefficients().1, omega)
}

fn german_shape(a: f64, omega: f64) -> f64 {
    let (wc2, wr2) = (
        GERMAN_CUTOFF * GERMAN_CUTOFF,
        GERMAN_ROLL_OFF * GERMAN_ROLL_OFF,
    );
    let w2 = omega * omega;
    a * wc2 / ((w2 + wr2) * (w2 + wc2))
}

/// Reference spatial frequency of ISO 8608, n₀ = 0.1 cycle/m.
pub const ISO_REFERENCE_FREQUENCY: f64 = 0.1;

impl IsoClass {
    /// G_d(n₀), m³ (= m²/(cycle/m)): the geometric mean of the class's
    /// range in ISO 8608 Table 1 (class A: < 32e-6, B: 32–128e-6, …, each
    /// class four times the previous).
    pub fn reference_density(self) -> f64 {
        16e-6 * 4f64.powi(self as i32)
    }
}

/// ISO 8608 road PSD, m²/(rad/m), one-sided, at wavenumber Ω (rad/m).
/// ISO 8608 writes G_d(n) = G_d(n₀) (n/n₀)^(−2) in m²/(cycle/m) of the
/// spatial frequency n (cycle/m), n₀ = 0.1 cycle/m; with n = Ω/2π and
/// G(Ω) dΩ = G_d(n) dn this is G(Ω) = G_d(n₀)/(2π) · (Ω/Ω₀)^(−2),
/// Ω₀ = 2π n₀. (ISO 8608 also tabulates the same classes by
/// G_d(Ω = 1 rad/m) = 1e-6 m³ for class A, which this reproduces.)
pub fn iso8608(class: IsoClass, omega: f64) -> f64 {
    let omega0 = 2.0 * PI * ISO_REFERENCE_FREQUENCY;
    class.reference_density() / (2.0 * PI) * (omega / omega0).powi(-2)
}

impl Spectrum {
    /// One-sided PSD at wavenumber `omega` (rad/m), m²/(rad/m).
    pub fn density(&self, omega: f64) -> f64 {
        match *self {
            Spectrum::Fra { class } => fra_vertical(class, omega),
            Spectrum::German { interference } => german_vertical(interference, omega),
            Spectrum::Iso8608 { class } => iso8608(class, omega),
            Spectrum::FraAlignment { class } => fra_alignment(class, omega),
            Spectrum::GermanAlignment { interference } => german_alignment(interference, omega),
        }
    }

    /// The alignment (lateral) spectrum of the same track, if it has one
    /// (a road's ISO class has none).
    pub fn alignment(&self) -> Option<Spectrum> {
        match *self {
            Spectrum::Fra { class } => Some(Spectrum::FraAlignment { class }),
            Spectrum::German { interference } => Some(Spectrum::GermanAlignment { interference }),
            _ => None,
        }
    }

    /// ∫ G(Ω) dΩ from `lo` to `hi` (rad/m) in closed form, m²: the variance
    /// of the profile over the band. FRA: Ω_c²/(Ω²(Ω²+Ω_c²)) =
    /// 1/Ω² − 1/(Ω²+Ω_c²); German: partial fractions in Ω_r and Ω_c; ISO:
    /// ∫ Ω⁻² dΩ.
    pub fn band_variance(&self, lo: f64, hi: f64) -> f64 {
        match *self {
            Spectrum::Fra { class } | Spectrum::FraAlignment { class } => {
                let row = FRA_CLASSES[usize::from(class.clamp(1, 6)) - 1];
                let coefficient = match self {
                    Spectrum::Fra { .. } => row.0,
                    _ => row.1,
                };
                let a = FRA_K * coefficient * CM2;
                let f = |w: f64| -1.0 / w - (w / FRA_CUTOFF).atan() / FRA_CUTOFF;
                a * (f(hi) - f(lo))
            }
            Spectrum::German { interference } | Spectrum::GermanAlignment { interference } => {
                let a = match self {
                    Spectrum::German { .. } => interference.coefficients().0,
                    _ => interference.coefficients().1,
                };
                let (wc, wr) = (GERMAN_CUTOFF, GERMAN_ROLL_OFF);
                let scale = a * wc * wc / (wc * wc - wr * wr);
                let f = |w: f64| (w / wr).atan() / wr - (w / wc).atan() / wc;
                scale * (f(hi) - f(lo))
            }
            Spectrum::Iso8608 { class } => {
                let omega0 = 2.0 * PI * ISO_REFERENCE_FREQUENCY;
                let c = class.reference_density() / (2.0 * PI) * omega0 * omega0;
                c * (1.0 / lo - 1.0 / hi)
            }
        }
    }

    /// A short name for labels: `fra5` (an FRA class as a study's
    /// `roughness` list names it), `german-low`, `iso-C`.
    pub fn label(&self) -> String {
        match *self {
            Spectrum::Fra { class } => format!("fra{class}"),
            Spectrum::German { interference } => match interference {
                Interference::Low => "german-low".into(),
                Interference::High => "german-high".into(),
            },
            Spectrum::Iso8608 { class } => format!("iso-{class:?}"),
            Spectrum::FraAlignment { class } => format!("fra{class}-alignment"),
            Spectrum::GermanAlignment { interference } => match interference {
                Interference::Low => "german-low-alignment".into(),
                Interference::High => "german-high-alignment".into(),
            },
        }
    }
}
