//! Resolved rail vehicles: the 10-DOF rail car and trains of them.

use serde::Serialize;

/// Four-axle rail car (10 DOFs).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct RailCar {
    /// Speed at t = 0, m/s.
    pub speed: f64,
    /// Constant acceleration along the path, m/s² (negative: braking; a
    /// vehicle that stops stays stopped); 0 for constant speed.
    pub acceleration: f64,
    /// Time the front wheelset reaches x = 0, s.
    pub entry_time: f64,
    /// Transverse position of the track's centre line on a plate deck, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_position: Option<f64>,
    /// Every parameter, preset values filled in.
    pub parameters: RailCarParameters,
}

/// Rail car parameters (see the raw format for each meaning); SI units.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct RailCarParameters {
    /// Car body mass M_c, kg.
    pub body_mass: f64,
    /// Car body pitch moment of inertia J_c, kg·m².
    pub body_pitch_inertia: f64,
    /// Mass of one bogie frame M_b, kg.
    pub bogie_mass: f64,
    /// Pitch moment of inertia of one bogie J_b, kg·m².
    pub bogie_pitch_inertia: f64,
    /// Mass of one wheelset M_w, kg.
    pub wheelset_mass: f64,
    /// Primary suspension stiffness per wheelset k_p, N/m.
    pub primary_stiffness: f64,
    /// Primary suspension damping per wheelset c_p, N·s/m.
    pub primary_damping: f64,
    /// Secondary suspension stiffness per bogie k_s, N/m.
    pub secondary_stiffness: f64,
    /// Secondary suspension damping per bogie c_s, N·s/m.
    pub secondary_damping: f64,
    /// Half the distance between the bogie centres a, m.
    pub half_bogie_spacing: f64,
    /// Half the distance between a bogie's two wheelsets b, m.
    pub half_wheelbase: f64,
}

/// A train of rail cars running together.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Train {
    /// Speed at t = 0, m/s.
    pub speed: f64,
    /// Constant acceleration along the path, m/s² (negative: braking; a
    /// vehicle that stops stays stopped); 0 for constant speed.
    pub acceleration: f64,
    /// Time the first car's front wheelset reaches x = 0, s.
    pub entry_time: f64,
    /// Transverse position of the track's centre line on a plate deck, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_position: Option<f64>,
    /// The cars, front first (the expansion of `count`/`car_spacing` or of
    /// the `cars` list). Car k's wheelsets are the train's wheels
    /// 4(k−1)+1 … 4k; its DOFs are named `car{k}_body_bounce`, ….
    pub cars: Vec<TrainCar>,
}

/// One car of a train.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct TrainCar {
    /// Distance from the front wheelset of the car ahead to this car's
    /// front wheelset, m; none for the first car. Written in place of
    /// `offset` so that the resolved file reads back as a `cars` list.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spacing: Option<f64>,
    /// Distance of the car's front wheelset behind the train's first
    /// wheelset, m: the running sum of `spacing` (summed in the same order
    /// on every load, so a resolved file resolves to itself bit for bit).
    #[serde(skip)]
    pub offset: f64,
    /// The car's parameters.
    pub parameters: RailCarParameters,
}

impl Train {
    /// Distance from the first wheelset back to the last one, m.
    pub fn length(&self) -> f64 {
        self.cars
            .last()
            .map_or(0.0, |c| c.offset + wheelset_span(&c.parameters))
    }
}

/// A train of 3D cars (`type: train_3d`, 27 DOFs per car) running together.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Train3d {
    /// Speed at t = 0, m/s.
    pub speed: f64,
    /// Constant acceleration along the path, m/s² (negative: braking; a
    /// vehicle that stops stays stopped); 0 for constant speed.
    pub acceleration: f64,
    /// Time the first car's front wheelset reaches x = 0, s.
    pub entry_time: f64,
    /// Transverse position of the track's centre line on a plate deck, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_position: Option<f64>,
    /// The cars, front first. Car k's wheelsets are wheels 12(k−1)+1 …
    /// 12k of the train (three per wheelset: left rail, right rail,
    /// lateral); its DOFs are named `car{k}_body_lateral`, ….
    pub cars: Vec<Train3dCar>,
}

/// One car of a 3D train.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Train3dCar {
    /// Distance from the front wheelset of the car ahead to this car's
    /// front wheelset, m; none for the first car. Written in place of
    /// `offset` so that the resolved file reads back as a `cars` list.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spacing: Option<f64>,
    /// Distance of the car's front wheelset behind the train's first
    /// wheelset, m: the running sum of `spacing` (summed in the same order
    /// on every load, so a resolved file resolves to itself bit for bit).
    #[serde(skip)]
    pub offset: f64,
    /// The car's parameters.
    pub parameters: Train3dParameters,
}

/// Parameters of one 3D car (see the raw format for each meaning); SI
/// units. Suspension rates are per spring: one primary spring set per axle
/// box (two per wheelset), one secondary set per side of a bogie.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Train3dParameters {
    /// Car body mass, kg.
    pub body_mass: f64,
    /// Car body roll moment of inertia (about x), kg·m².
    pub body_roll_inertia: f64,
    /// Car body pitch moment of inertia (about y), kg·m².
    pub body_pitch_inertia: f64,
    /// Car body yaw moment of inertia (about z), kg·m².
    pub body_yaw_inertia: f64,
    /// Mass of one bogie frame, kg.
    pub bogie_mass: f64,
    /// Bogie roll moment of inertia, kg·m².
    pub bogie_roll_inertia: f64,
    /// Bogie pitch moment of inertia, kg·m².
    pub bogie_pitch_inertia: f64,
    /// Bogie yaw moment of inertia, kg·m².
    pub bogie_yaw_inertia: f64,
    /// Mass of one wheelset, kg.
    pub wheelset_mass: f64,
    /// Wheelset roll moment of inertia, kg·m².
    pub wheelset_roll_inertia: f64,
    /// Primary suspension per axle box, longitudinal / lateral / vertical, N/m.
    pub primary_stiffness: [f64; 3],
    /// Primary suspension damping per axle box, longitudinal / lateral / vertical, N·s/m.
    pub primary_damping: [f64; 3],
    /// Secondary suspension per side of a bogie, longitudinal / lateral / vertical, N/m.
    pub secondary_stiffness: [f64; 3],
    /// Secondary suspension damping per side of a bogie, N·s/m.
    pub secondary_damping: [f64; 3],
    /// Half the distance between the bogie centres, m.
    pub half_bogie_spacing: f64,
    /// Half the distance between a bogie's two wheelsets, m.
    pub half_wheelbase: f64,
    /// Half the lateral distance between the two primary suspensions of a wheelset, m.
    pub primary_half_spacing: f64,
    /// Half the lateral distance between the two secondary suspensions of a bogie, m.
    pub secondary_half_spacing: f64,
    /// Half the lateral distance between a wheelset's two wheel–rail contact points, m.
    pub contact_half_spacing: f64,
    /// Height of the car body's centre of gravity above the rail head, m.
    pub body_height: f64,
    /// Height of a bogie's centre of gravity above the rail head, m.
    pub bogie_height: f64,
    /// Height of the secondary suspension above the rail head, m.
    pub secondary_height: f64,
    /// Nominal rolling radius: the height of the axle (and of the primary
    /// suspension) above the rail head, m.
    pub wheel_radius: f64,
}

impl Train3d {
    /// Distance from the first wheelset back to the last one, m.
    pub fn length(&self) -> f64 {
        self.cars.last().map_or(0.0, |c| {
            c.offset + 2.0 * (c.parameters.half_bogie_spacing + c.parameters.half_wheelbase)
        })
    }
}

/// Written with the raw format's flat names (`primary_lateral_stiffness`,
/// …) so that the resolved file loads back unchanged.
impl Serialize for Train3dParameters {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut out = serializer.serialize_struct("Train3dParameters", 31)?;
        out.serialize_field("body_mass", &self.body_mass)?;
        out.serialize_field("body_roll_inertia", &self.body_roll_inertia)?;
        out.serialize_field("body_pitch_inertia", &self.body_pitch_inertia)?;
        out.serialize_field("body_yaw_inertia", &self.body_yaw_inertia)?;
        out.serialize_field("bogie_mass", &self.bogie_mass)?;
        out.serialize_field("bogie_roll_inertia", &self.bogie_roll_inertia)?;
        out.serialize_field("bogie_pitch_inertia", &self.bogie_pitch_inertia)?;
        out.serialize_field("bogie_yaw_inertia", &self.bogie_yaw_inertia)?;
        out.serialize_field("wheelset_mass", &self.wheelset_mass)?;
        out.serialize_field("wheelset_roll_inertia", &self.wheelset_roll_inertia)?;
        let [kx, ky, kz] = self.primary_stiffness;
        out.serialize_field("primary_longitudinal_stiffness", &kx)?;
        out.serialize_field("primary_lateral_stiffness", &ky)?;
        out.serialize_field("primary_vertical_stiffness", &kz)?;
        let [cx, cy, cz] = self.primary_damping;
        out.serialize_field("primary_longitudinal_damping", &cx)?;
        out.serialize_field("primary_lateral_damping", &cy)?;
        out.serialize_field("primary_vertical_damping", &cz)?;
        let [kx, ky, kz] = self.secondary_stiffness;
        out.serialize_field("secondary_longitudinal_stiffness", &kx)?;
        out.serialize_field("secondary_lateral_stiffness", &ky)?;
        out.serialize_field("secondary_vertical_stiffness", &kz)?;
        let [cx, cy, cz] = self.secondary_damping;
        out.serialize_field("secondary_longitudinal_damping", &cx)?;
        out.serialize_field("secondary_lateral_damping", &cy)?;
        out.serialize_field("secondary_vertical_damping", &cz)?;
        out.serialize_field("half_bogie_spacing", &self.half_bogie_spacing)?;
        out.serialize_field("half_wheelbase", &self.half_wheelbase)?;
        out.serialize_field("primary_half_spacing", &self.primary_half_spacing)?;
        out.serialize_field("secondary_half_spacing", &self.secondary_half_spacing)?;
        out.serialize_field("contact_half_spacing", &self.contact_half_spacing)?;
        out.serialize_field("body_height", &self.body_height)?;
        out.serialize_field("bogie_height", &self.bogie_height)?;
        out.serialize_field("secondary_height", &self.secondary_height)?;
        out.serialize_field("wheel_radius", &self.wheel_radius)?;
        out.end()
    }
}

/// Distance from the car's front wheelset back to its rear wheelset, m.
pub fn wheelset_span(p: &RailCarParameters) -> f64 {
    2.0 * (p.half_bogie_spacing + p.half_wheelbase)
}
