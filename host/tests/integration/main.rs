//! The host's integration tests, as one test binary: each module was a
//! file of its own under `host/tests/` and keeps its name, so
//! `cargo test -p fwav --test integration design::` runs one group. One
//! binary links the `fwav` library and its heavy dependencies (faer,
//! nalgebra, plotters, rayon) once instead of once a file, and its test
//! threads take the tests of every module, so a long test of one module
//! no longer leaves a core idle while the next file waits (CI's time).
//!
//! Three modules are not groups but helpers the groups share: `program`,
//! which runs the `fwav` program as a user does and gives a test its
//! scratch directory; `vtk_reader`, which
//! reads the ParaView files the programs write with VTK's own reader,
//! and `machine_time`, what the machine gave a benchmark while it ran.
//!
//! The modules share one process: their scratch files carry the module's
//! own prefix besides the process id, and none sets an environment
//! variable, changes the current directory or installs a global
//! subscriber.

mod aero2d;
mod aero2d_panel;
mod aeroelastic;
mod cli;
mod cli_messages;
mod design;
mod design_safety;
mod discipline;
mod discipline_ns;
mod discipline_ns_scatter;
mod discipline_ns_scores;
mod input_checks;
mod machine_time;
mod optimize;
mod program;
mod shell;
mod study;
mod topology;
mod user_files;
mod uvlm;
mod validate;
mod viscous_default_section;
mod viscous_field;
mod viscous_section;
mod viscous_shapes;
mod viscous_stream;
mod vtk_reader;
