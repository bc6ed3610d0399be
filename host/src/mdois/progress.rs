//! What the driver reports as it goes, for a progress display: the cycle,
//! the stage, what happened, and the time since the driver started. The
//! two disciplines run at the same time, so reports of both interleave.

use std::time::Duration;

use super::state::Stage;

/// One report.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Progress {
    /// Design cycle from 1.
    pub cycle: usize,
    /// The stage.
    pub stage: Stage,
    /// What happened.
    pub event: Event,
    /// Time since this invocation of the driver started.
    pub elapsed: Duration,
}

/// What happened in a stage.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Event {
    /// The stage was finished by an earlier invocation; its files are
    /// reused.
    Reused,
    /// The stage started.
    Started,
    /// Work done within the stage: time steps of the system analysis, 2D
    /// evaluations of the aerodynamic discipline, time steps of an ESLSO
    /// cycle's dynamic analysis (`inner` is that ESLSO cycle).
    Advanced {
        /// Units done.
        done: usize,
        /// Units in all.
        total: usize,
        /// The ESLSO cycle, for the structural discipline.
        inner: Option<usize>,
    },
    /// An ESLSO cycle ended.
    InnerCycle {
        /// The ESLSO cycle from 1.
        inner: usize,
        /// Elements its 0/1 transformation changed.
        elements_changed: usize,
    },
    /// The stage finished and its files are written.
    Finished {
        /// Its wall time, s.
        seconds: f64,
    },
}
