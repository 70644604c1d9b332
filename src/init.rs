//! `vbi init`: a commented starter scene for a chosen bridge and vehicle.
//!
//! A new user's first scene is the hardest: which keys are required, which
//! units, what to record. The starter is a complete, physically sensible
//! crossing (every number states its unit and where it comes from) that
//! `vbi check` accepts and `vbi run` runs in seconds; the user edits it into
//! their own. Each bridge × vehicle pair that the models support has a
//! starter (tests/init.rs checks and runs every one); the others are refused
//! with the list of pairs.

use std::fmt::Write as _;

/// The bridges a starter can hold.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum StarterBridge {
    /// A simply supported Euler–Bernoulli beam (25 m road or 32 m railway span).
    Beam,
    /// A three-span orthotropic Kirchhoff plate deck (the plate paper's road bridge).
    Plate,
}

/// The vehicles a starter can hold.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
#[value(rename_all = "snake_case")]
pub enum StarterVehicle {
    /// Constant axle loads (no vehicle dynamics); the starter's two 100 kN
    /// axles 4 m apart are an example, from no standard (AASHTO's trucks are
    /// `type: aashto_h20_44` and `aashto_hs20_44` in the scene).
    MovingForce,
    /// A sprung mass on a spring (the Yang & Yau 1997 benchmark).
    Oscillator,
    /// The plate paper's 7-DOF two-axle truck, which it calls H20-44 (its
    /// Section 2.2; static wheel forces 58.81 kN front, 32.42 kN rear, its
    /// Section 3.2): not AASHTO's H20-44 axle loads of 35.6 and 142.3 kN.
    H20_44,
    /// The LCP paper's 10-DOF rail car (its Section 5.2, Table 2).
    RailCar,
    /// A train of the LCP paper's rail cars (Table 2).
    Train,
    /// The EMBS paper's 3D car, AVE-S103 (its Table 2; needs a 3D beam: the
    /// starter gives one).
    #[value(name = "train_3d")]
    Train3d,
    /// An HSLM-A train of moving axle loads (EN 1991-2:2003 Annex E, Table
    /// E.1), with the resonance check.
    Hslm,
}

impl StarterBridge {
    fn key(self) -> &'static str {
        match self {
            Self::Beam => "beam",
            Self::Plate => "plate",
        }
    }
}

impl StarterVehicle {
    fn key(self) -> &'static str {
        match self {
            Self::MovingForce => "moving_force",
            Self::Oscillator => "oscillator",
            Self::H20_44 => "h20_44",
            Self::RailCar => "rail_car",
            Self::Train => "train",
            Self::Train3d => "train_3d",
            Self::Hslm => "hslm",
        }
    }

    /// Railway vehicles run on a railway span with a rail surface.
    fn is_railway(self) -> bool {
        matches!(
            self,
            Self::RailCar | Self::Train | Self::Train3d | Self::Hslm
        )
    }
}

/// A pair no starter exists for.
#[derive(Debug, thiserror::Error)]
#[error(
    "no starter scene for a `{vehicle}` on a `{bridge}`: railway vehicles (rail_car, train, \
     train_3d, hslm) start on `--bridge beam`; a plate deck takes moving_force, oscillator \
     or h20_44"
)]
pub struct NoStarter {
    /// The bridge asked for.
    pub bridge: &'static str,
    /// The vehicle asked for.
    pub vehicle: &'static str,
}

/// The starter scene's text. `schema` is the modeline's schema path as the
/// editor should resolve it (relative to the scene file).
///
/// # Errors
/// [`NoStarter`] for a pair the models do not combine.
pub fn starter(
    bridge: StarterBridge,
    vehicle: StarterVehicle,
    schema: &str,
) -> Result<String, NoStarter> {
    if bridge == StarterBridge::Plate && vehicle.is_railway() {
        return Err(NoStarter {
            bridge: bridge.key(),
            vehicle: vehicle.key(),
        });
    }
    let mut scene = String::new();
    let _ = writeln!(scene, "# yaml-language-server: $schema={schema}");
    let _ = writeln!(
        scene,
        "# A starter scene written by `vbi init --bridge {} --vehicle {}`.\n\
         # Check it with `vbi check FILE`, run it with `vbi run FILE`; every key is\n\
         # described in docs/format.md (or `vbi schema --markdown`). A plain number\n\
         # is SI (m, kg, s, N); any physical value may carry its unit instead\n\
         # (`25 m`, `40 t`, `170 kN`, `1.6e6 N/m`, `90 km/h`).",
        bridge.key(),
        vehicle.key()
    );
    let _ = writeln!(
        scene,
        "name: my-{}-{}",
        bridge.key(),
        vehicle.key().replace('_', "-")
    );
    let _ = writeln!(
        scene,
        "description: >\n  Starter scene: replace with what this crossing is and where its numbers\n  come from."
    );
    scene.push_str(bridge_block(bridge, vehicle));
    scene.push_str(vehicle_block(bridge, vehicle));
    scene.push_str(surface_block(bridge, vehicle));
    scene.push_str(record_block(bridge, vehicle));
    if vehicle == StarterVehicle::Hslm {
        scene.push_str(
            "# The EN 1991-2 6.4.6 resonance check: every train over a speed grid up to\n\
             # 1.2 × the line speed, refined at each resonance speed f0·D/k; the run\n\
             # exits 3 when a train exceeds the deck-acceleration limit.\n\
             study:\n  type: resonance_check\n  trains: [A1, A5, A10]\n  line_speed: 200 km/h\n  \
             speeds: {from: 120 km/h, to: 240 km/h, step: 40 km/h}\n  deck: ballasted\n",
        );
    }
    Ok(scene)
}

fn bridge_block(bridge: StarterBridge, vehicle: StarterVehicle) -> &'static str {
    match (bridge, vehicle) {
        (StarterBridge::Plate, _) => {
            "# Three-span jointless concrete slab, 12-16-12 m, 10 m wide, 0.8 m thick\n\
             # (the plate paper's first example; E = 35 GPa, nu = 0.2, 2500 kg/m3).\n\
             bridge:\n  type: plate\n  spans: [12.0, 16.0, 12.0]   # m\n  width: 10.0                 # m\n  \
             thickness: 0.8              # m\n  density: 2500.0             # kg/m3\n  \
             rigidity: {type: isotropic, youngs_modulus: 3.5e10, poisson_ratio: 0.2}   # Pa, -\n  \
             modes: {count: 30}\n  damping: {type: modal, ratio: 0.02}   # 2 % in every mode\n"
        }
        (StarterBridge::Beam, StarterVehicle::Train3d) => {
            "# A 3D simply supported 25 m railway span: vertical and lateral bending and\n\
             # torsion (doubly symmetric box girder, fork supports).\n\
             bridge:\n  type: beam\n  spans: [25.0]                    # m\n  \
             bending_stiffness: 1.2e11        # EI, N·m²\n  mass_per_length: 20000.0         # kg/m\n  \
             lateral_bending_stiffness: 4.0e11   # EI_z, N·m²\n  torsional_stiffness: 1.0e11     # GJ, N·m²/rad\n  \
             polar_mass: 100000.0             # kg·m²/m\n  rail_height: 1.0                 # m above the shear centre\n  \
             damping: {type: modal, ratio: 0.02}\n"
        }
        (StarterBridge::Beam, StarterVehicle::Hslm) => {
            "# A simply supported 20 m ballasted railway span, f1 = 5.0 Hz, 1 % damping\n\
             # (EN 1991-2 Table 6.6 for L >= 20 m).\n\
             bridge:\n  type: beam\n  spans: [20.0]                    # m\n  \
             bending_stiffness: 2.43e10       # EI, N·m²\n  mass_per_length: 15000.0         # kg/m\n  \
             # Every mode up to the deck-acceleration filter, the greater of 30 Hz,\n  \
             # 1.5 f1 and f3 (EN 1991-2 6.4.6.5(3), EN 1990 A2.4.4.2.1(4); here\n  \
             # f3 = 9 f1 = 45 Hz); a cap below it warns.\n  \
             modes: {max_frequency: 50.0}     # Hz\n  \
             damping: {type: modal, ratio: 0.01}\n"
        }
        (StarterBridge::Beam, v) if v.is_railway() => {
            "# A simply supported 32 m railway span (the LCP paper's beam: f1 = 1.62 Hz).\n\
             bridge:\n  type: beam\n  spans: [32.0]                    # m\n  \
             bending_stiffness: 1.3448174e10  # EI, N·m²\n  mass_per_length: 12000.0         # kg/m\n  \
             damping: {type: modal, ratio: 0.02}   # 2 % in every mode\n"
        }
        (StarterBridge::Beam, _) => {
            "# A simply supported 25 m road bridge (the Yang & Yau 1997 benchmark beam).\n\
             bridge:\n  type: beam\n  spans: [25.0]                  # m\n  \
             bending_stiffness: 8.323e9     # EI, N·m²\n  mass_per_length: 2303.0        # kg/m\n  \
             damping: {type: modal, ratio: 0.02}   # 2 % in every mode\n"
        }
    }
}

fn vehicle_block(bridge: StarterBridge, vehicle: StarterVehicle) -> &'static str {
    match vehicle {
        StarterVehicle::MovingForce => {
            "vehicles:\n  - type: moving_force        # an example; AASHTO's trucks: aashto_h20_44, aashto_hs20_44\n    \
             loads: [100000.0, 100000.0]   # N, per axle\n    \
             axle_spacings: [4.0]           # m between the axles\n    speed: 80 km/h\n"
        }
        StarterVehicle::Oscillator => {
            "vehicles:\n  - type: oscillator\n    sprung_mass: 5750.0     # kg\n    \
             unsprung_mass: 0.0      # kg (massless wheel)\n    stiffness: 1.595e6      # N/m\n    \
             speed: 100 km/h\n"
        }
        StarterVehicle::H20_44 if bridge == StarterBridge::Plate => {
            "vehicles:\n  - type: h20_44            # the plate paper's 7-DOF truck (Sec. 2.2; 58.81/32.42 kN\n    \
             #   per front/rear wheel, Sec. 3.2): not AASHTO's H20-44 loads (aashto_h20_44)\n    \
             speed: 90 km/h\n    lateral_position: 1.915   # m, right tyres from the deck's y = 0 edge\n"
        }
        StarterVehicle::H20_44 => {
            "vehicles:\n  - type: h20_44            # the plate paper's 7-DOF truck (Sec. 2.2; 58.81/32.42 kN\n    \
             #   per front/rear wheel, Sec. 3.2): not AASHTO's H20-44 loads (aashto_h20_44)\n    \
             speed: 90 km/h\n"
        }
        StarterVehicle::RailCar => {
            "vehicles:\n  - type: rail_car          # the LCP paper's 10-DOF car (Table 2)\n    speed: 160 km/h\n"
        }
        StarterVehicle::Train => {
            "vehicles:\n  - type: train             # the LCP paper's rail cars (Table 2) coupled in a row\n    \
             count: 3\n    car_spacing: 25.0        # m, front wheelset to front wheelset\n    \
             speed: 160 km/h\n"
        }
        StarterVehicle::Train3d => {
            "vehicles:\n  - type: train_3d          # the EMBS paper's 3D car (Table 2)\n    speed: 200 km/h\n"
        }
        StarterVehicle::Hslm => {
            "vehicles:\n  - {type: hslm, model: A1, speed: 200 km/h}   # EN 1991-2 Annex E, Table E.1\n"
        }
    }
}

fn surface_block(bridge: StarterBridge, vehicle: StarterVehicle) -> &'static str {
    match (bridge, vehicle) {
        (_, StarterVehicle::Hslm | StarterVehicle::MovingForce) => "",
        (_, StarterVehicle::Train3d) => {
            "# German low-interference track (vertical profile and alignment), faded in\n\
             # over its longest wavelength from where the wheels first meet it.\n\
             surface: {type: german, interference: low, alignment: true, seed: 1}\n\
             # The EMBS formulation holds the wheelsets on their rails.\n\
             contact: {type: permanent}\n"
        }
        (_, v) if v.is_railway() => {
            "# FRA class 6 track (maintained for 110 mph = 177 km/h, 49 CFR 213.307): a\n\
             # random rail profile, seed fixed so runs repeat.\n\
             surface: {type: fra, class: 6, seed: 1}\n\
             contact: {type: elastic, stiffness: 1.0e9}   # N/m per wheelset: the wheel may lift off\n"
        }
        _ => {
            "# ISO 8608 class A road (very good), seed fixed so runs repeat.\n\
             surface: {type: iso8608, class: A, seed: 1}\n"
        }
    }
}

fn record_block(bridge: StarterBridge, vehicle: StarterVehicle) -> &'static str {
    match (bridge, vehicle) {
        (StarterBridge::Plate, StarterVehicle::H20_44) => {
            "record:\n  - {name: span2_centre, quantity: bridge_displacement, x: 20.0, y: 5.0}\n  \
             - {name: span2_centre_acceleration, quantity: bridge_acceleration, x: 20.0, y: 5.0}\n  \
             - {name: front_right_force, quantity: contact_force, wheel: 1}\n"
        }
        (StarterBridge::Plate, _) => {
            "record:\n  - {name: span2_centre, quantity: bridge_displacement, x: 20.0, y: 5.0}\n  \
             - {name: span2_centre_acceleration, quantity: bridge_acceleration, x: 20.0, y: 5.0}\n"
        }
        (StarterBridge::Beam, StarterVehicle::Hslm) => {
            "record:\n  - {name: midspan, quantity: bridge_displacement, x: 10.0}\n  \
             - {name: midspan_acceleration, quantity: bridge_acceleration, x: 10.0}\n"
        }
        (StarterBridge::Beam, StarterVehicle::MovingForce) => {
            "record:\n  - {name: midspan, quantity: bridge_displacement, x: 12.5}\n  \
             - {name: midspan_moment, quantity: bridge_moment, x: 12.5}\n"
        }
        (StarterBridge::Beam, StarterVehicle::Oscillator | StarterVehicle::H20_44) => {
            "record:\n  - {name: midspan, quantity: bridge_displacement, x: 12.5}\n  \
             - {name: midspan_acceleration, quantity: bridge_acceleration, x: 12.5}\n  \
             - {name: contact_force, quantity: contact_force, wheel: 1}\n"
        }
        (StarterBridge::Beam, StarterVehicle::Train3d) => {
            "record:\n  - {name: midspan, quantity: bridge_displacement, x: 12.5}\n  \
             - {name: midspan_lateral, quantity: bridge_displacement, x: 12.5, direction: uy}\n  \
             - {name: wheel1_force, quantity: contact_force, wheel: 1}\n"
        }
        (StarterBridge::Beam, StarterVehicle::Train) => {
            "record:\n  - {name: midspan, quantity: bridge_displacement, x: 16.0}\n  \
             - {name: midspan_acceleration, quantity: bridge_acceleration, x: 16.0}\n  \
             - {name: car1_body_acceleration, quantity: vehicle_acceleration, car: 1, dof: body_bounce}\n  \
             - {name: wheel1_force, quantity: contact_force, wheel: 1}\n"
        }
        (StarterBridge::Beam, _) => {
            "record:\n  - {name: midspan, quantity: bridge_displacement, x: 16.0}\n  \
             - {name: midspan_acceleration, quantity: bridge_acceleration, x: 16.0}\n  \
             - {name: body_acceleration, quantity: vehicle_acceleration, dof: body_bounce}\n  \
             - {name: wheel1_force, quantity: contact_force, wheel: 1}\n"
        }
    }
}
