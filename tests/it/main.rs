//! The integration tests, as one crate (issue 25, point 4): every file here
//! is a module of one test binary, so `cargo test --release` builds and links
//! the library into one test executable instead of one per file (a cold
//! build of 48 binaries took most of CI's time). Run a part of it by module
//! path: `cargo test --release --test it fuzz::`. A new test file goes here
//! as `mod name;` below; it shares `support` (the independent reference
//! solutions and helpers), which is compiled once for all of them.
//!
//! The modules run in one process, on the harness's threads: a test must not
//! set environment variables or the working directory in-process (none does:
//! the child `vbi` processes get theirs through `Command`), and scratch
//! folders carry the module's name as well as the process id.

mod support;

mod accelerating;
mod advice;
mod automatic;
mod automatic_shipped;
mod bad_inputs;
mod bare_tags;
mod beam_3d;
mod beam_mesh;
mod cancel;
mod cli;
mod confined;
mod converge;
mod csv_headers;
mod direct;
mod documented_defaults;
mod embs;
mod event_reference_oracle;
mod fe_import;
mod fe_import_entries;
mod fe_import_opensees;
mod fe_import_rotations;
mod fuzz;
mod generate;
mod golden;
mod ground_guard;
mod ground_motion;
mod hard_cases;
mod hertz;
mod hostile;
mod hostile_store;
mod lateral_geometry;
mod library_api;
mod lsp;
mod many_modes;
mod merge_memory;
mod modes_cache;
mod modes_left_out;
mod monte_carlo;
mod moreau_jean;
mod multi_wheel;
mod multi_wheel_lift;
mod nonsense;
mod one_round;
mod output;
mod physics;
mod plan_order;
mod plate;
mod plate_truck;
mod plots;
mod presets;
mod profile_entrance;
mod rail_car;
mod regress;
mod resolved_anywhere;
mod resolved_rerun;
mod resonance;
mod resonance_verdict;
mod schema;
mod section_forces;
mod separation;
mod shard;
mod shipped_clean;
mod shipped_converged;
mod slurm;
mod speed_sweep;
mod speed_units;
mod support_reactions;
mod surfaces;
mod train_3d;
mod truck;
mod trust;
mod units;
mod untrusted;
