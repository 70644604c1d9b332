//! The vehicles' degree-of-freedom names and wheel counts, as `record: …
//! dof:` and `wheel:` name them: plain tables the format checks records
//! against and the vehicle models number their DOFs by (the models
//! re-export them, so one table serves both).

/// The two-mass oscillator.
pub mod oscillator {
    /// DOF names, as used by `record: … dof:`.
    pub const DOF_NAMES: [&str; 2] = ["sprung", "wheel"];
}

/// The H20-44 truck.
pub mod h20_44 {
    /// DOF names, as used by `record: … dof:`.
    pub const DOF_NAMES: [&str; 11] = [
        "body_bounce",
        "body_pitch",
        "body_roll",
        "front_axle_bounce",
        "front_axle_roll",
        "rear_axle_bounce",
        "rear_axle_roll",
        "wheel1",
        "wheel2",
        "wheel3",
        "wheel4",
    ];
}

/// The 2D rail car and train.
pub mod rail_car {
    /// DOF names of one car, as used by `record: … dof:`.
    pub const DOF_NAMES: [&str; 10] = [
        "body_bounce",
        "body_pitch",
        "front_bogie_bounce",
        "front_bogie_pitch",
        "rear_bogie_bounce",
        "rear_bogie_pitch",
        "wheelset1",
        "wheelset2",
        "wheelset3",
        "wheelset4",
    ];

    /// Wheelsets of one car.
    pub const WHEELSETS: usize = 4;

    /// Name of DOF `dof` (a name of [`DOF_NAMES`]) of car `car` (from 1) of a train.
    pub fn train_dof_name(car: usize, dof: &str) -> String {
        format!("car{car}_{dof}")
    }
}

/// The 3D train.
pub mod train_3d {
    /// DOFs of one car.
    pub const DOFS: usize = 27;
    /// Wheelsets of one car.
    pub const WHEELSETS: usize = 4;
    /// Wheels (contacts) per wheelset: left rail, right rail, lateral.
    pub const CONTACTS_PER_WHEELSET: usize = 3;

    /// DOF names of one car, as used by `record: … dof:` (a train prefixes
    /// `car{k}_`).
    pub const DOF_NAMES: [&str; DOFS] = [
        "body_lateral",
        "body_bounce",
        "body_yaw",
        "body_roll",
        "body_pitch",
        "front_bogie_lateral",
        "front_bogie_bounce",
        "front_bogie_yaw",
        "front_bogie_roll",
        "front_bogie_pitch",
        "rear_bogie_lateral",
        "rear_bogie_bounce",
        "rear_bogie_yaw",
        "rear_bogie_roll",
        "rear_bogie_pitch",
        "wheelset1_lateral",
        "wheelset1_left",
        "wheelset1_right",
        "wheelset2_lateral",
        "wheelset2_left",
        "wheelset2_right",
        "wheelset3_lateral",
        "wheelset3_left",
        "wheelset3_right",
        "wheelset4_lateral",
        "wheelset4_left",
        "wheelset4_right",
    ];
}
