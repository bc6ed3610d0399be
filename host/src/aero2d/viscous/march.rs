//! A viscous run's time stepping and load sampling: the ladder of steps
//! that follows the flow ([`StepControl`]) and the sampling of the loads
//! at a fixed interval, across a spin-up's hand-over from one grid to
//! the next ([`March`]).

use fwav_ns2d::{Flow, NsError};

use super::{FlowField, FrameSink, History, SectionPath, ViscousError, MAX_VISCOUS_STEPS};

/// Steps between checks of the stable time step (a check costs about a
/// tenth of a step).
const CHECK_EVERY: usize = 20;

/// Fewest load samples a period.
const SAMPLES_PER_PERIOD: f64 = 200.0;

/// The ratio of neighbouring rungs of [`StepControl`]'s ladder, 2^¼ (a
/// ladder of √2 took about 9 % more steps for the same error on the default
/// section's first stroke).
const STEP_RATIO: f64 = 1.189_207_115_002_721;

/// A step is lengthened only when the longer one keeps the Courant number
/// this far within the chosen one, so that it does not go up and down at
/// every check.
const LENGTHEN_MARGIN: f64 = 0.9;

/// The time step of a run: a rung `first · 2^(level/4)` of a ladder, at every
/// check the longest whose largest Courant number is within the chosen
/// one, up to the load sampling interval. The flow's fastest cells (a thin
/// plate's edges) are fast only in parts of a stroke: a step fixed at the
/// stroke's worst (halved when outgrown, never lengthened) ran most of the
/// default section's stroke at a Courant number of 0.5-0.8. The rungs are
/// few, so each rung's wall influence matrix is built once
/// ([`fwav_ns2d::Flow::step`] keeps them).
struct StepControl {
    first: f64,
    level: i32,
    top: i32,
    courant: f64,
}

impl StepControl {
    /// A ladder through `first`, at most `cap`, holding Courant number
    /// `courant`.
    fn new(first: f64, cap: f64, courant: f64) -> Self {
        let top = ((cap / first).ln() / STEP_RATIO.ln() + 1e-9).floor() as i32;
        Self {
            first,
            level: 0,
            top: top.max(0),
            courant,
        }
    }

    /// The current step.
    fn dt(&self) -> f64 {
        self.first * STEP_RATIO.powi(self.level)
    }

    /// Choose the step for the flow as it is now (shortened when the
    /// flow has outgrown it, lengthened when it has room).
    ///
    /// # Errors
    /// [`ViscousError::TooManySteps`] when the run would then take more
    /// than [`MAX_VISCOUS_STEPS`].
    fn adjust(
        &mut self,
        flow: &Flow<SectionPath>,
        duration: f64,
        steps: usize,
    ) -> Result<(), ViscousError> {
        let target = self.courant * flow.stable_dt(1.0);
        while self.dt() > target {
            self.level -= 1;
        }
        while self.level < self.top
            && self.first * STEP_RATIO.powi(self.level + 1) <= LENGTHEN_MARGIN * target
        {
            self.level += 1;
        }
        let dt = self.dt();
        let left = ((duration - flow.time()) / dt).ceil() as usize;
        if steps + left > MAX_VISCOUS_STEPS {
            return Err(ViscousError::TooManySteps {
                dt,
                time: flow.time(),
                steps: steps + left,
                max: MAX_VISCOUS_STEPS,
            });
        }
        Ok(())
    }
}

/// The loads at one instant: `(CL, CT, CP)`.
///
/// The input power is the work rate of the section's motion relative to
/// steady flight, as in the inviscid models and Garrick's (1936) theory
/// (`P = -L dh/dt - M dα/dt`, and the efficiency `T U / P`). The solver's
/// [`fwav_ns2d::WallLoads::power`] is the wall's whole work rate on the
/// fluid, which also counts the flight at `U` through it: `-T U` (the
/// force `F` times the flight velocity `(-U, 0)`, with `T = -F_x`). So
/// `CP = 2 power + CT`; a section at rest in the stream has none.
fn coefficients<M: fwav_ns2d::Motion>(flow: &Flow<M>) -> [f64; 3] {
    let loads = flow.loads();
    let ct = -2.0 * loads.force.re;
    [2.0 * loads.force.im, ct, 2.0 * loads.power + ct]
}

/// The sampling of a run's loads as its flows step ([`March::to`]).
pub(super) struct March {
    /// The motion, the largest Courant number of a step and the whole
    /// run's length (for the step count's check), chords travelled.
    path: SectionPath,
    courant: f64,
    duration: f64,
    /// The sampling interval, chords travelled, and the samples so far.
    pub(super) sample: f64,
    pub(super) history: History,
    /// The next sample's time.
    next: f64,
    /// Steps taken, and of them on the spin-up's grid.
    pub(super) steps: usize,
    pub(super) spin_up_steps: usize,
    /// The smallest step (or first step chosen), chords travelled.
    pub(super) smallest: f64,
    /// The flows handed on for a series ([`Self::keep_frames`]): how
    /// many, at what interval, the next one's time, those handed on so
    /// far and the last one's time.
    frames_wanted: usize,
    frame_every: f64,
    next_frame: f64,
    frames_taken: usize,
    last_frame_time: f64,
}

/// The interval of a run's load samples, chords travelled: a 200th of
/// the period of a motion of reduced frequency `reduced_frequency`, or a
/// 2000th of `duration` without a period (`reduced_frequency` 0).
pub(crate) fn load_interval(reduced_frequency: f64, duration: f64) -> f64 {
    if reduced_frequency > 0.0 {
        std::f64::consts::PI / reduced_frequency / SAMPLES_PER_PERIOD
    } else {
        duration / 2000.0
    }
}

impl March {
    /// A run of `path` to `duration` at steps of Courant number
    /// `courant`, sampling every `period / 200` (or `duration / 2000`
    /// without a period), from the first sample.
    pub(super) fn new(path: SectionPath, duration: f64, courant: f64) -> Self {
        let sample = load_interval(path.reduced_frequency(), duration);
        Self {
            path,
            courant,
            duration,
            sample,
            history: History::default(),
            next: sample,
            steps: 0,
            spin_up_steps: 0,
            smallest: f64::INFINITY,
            frames_wanted: 0,
            frame_every: f64::INFINITY,
            next_frame: f64::INFINITY,
            frames_taken: 0,
            last_frame_time: f64::NEG_INFINITY,
        }
    }

    /// Hand on `count` flows, at `i / count` of the run's length for `i` =
    /// 1 to `count`, each at the end of the first step that reaches it (a
    /// step that reaches several hands on one: at most `count`).
    pub(super) fn keep_frames(&mut self, count: usize) {
        if count > 0 {
            self.frames_wanted = count;
            self.frame_every = self.duration / count as f64;
            self.next_frame = self.frame_every;
        }
    }

    /// Hands `sink` the run's last flow `end` if frames were asked for
    /// and the last step did not reach the last frame's time (by
    /// rounding).
    ///
    /// # Errors
    /// [`ViscousError::Frame`] when `sink` fails.
    pub(super) fn last_frame(
        &mut self,
        end: &FlowField,
        sink: &mut dyn FrameSink,
    ) -> Result<(), ViscousError> {
        if self.frames_wanted > 0 && self.last_frame_time < end.time {
            self.hand_on(end, sink)?;
        }
        Ok(())
    }

    /// Hands `sink` the flow of `flow` if it has reached the next frame's
    /// time.
    fn frame(
        &mut self,
        flow: &Flow<SectionPath>,
        sink: &mut dyn FrameSink,
    ) -> Result<(), ViscousError> {
        let reached = flow.time() + 1e-9 * self.sample;
        if self.frames_taken < self.frames_wanted && reached >= self.next_frame {
            self.hand_on(&FlowField::of(flow, &self.path), sink)?;
            while self.next_frame <= reached {
                self.next_frame += self.frame_every;
            }
        }
        Ok(())
    }

    /// Hands `frame` to `sink`, counting it.
    fn hand_on(&mut self, frame: &FlowField, sink: &mut dyn FrameSink) -> Result<(), ViscousError> {
        sink.take(frame).map_err(|source| ViscousError::Frame {
            time: frame.time,
            source,
        })?;
        self.frames_taken += 1;
        self.last_frame_time = frame.time;
        Ok(())
    }

    /// Steps `flow` through the samples up to `until` (the step that
    /// reaches the last of them ends it), handing `frames` the flows
    /// asked for ([`Self::keep_frames`]).
    pub(super) fn to(
        &mut self,
        flow: &mut Flow<SectionPath>,
        until: f64,
        frames: &mut dyn FrameSink,
    ) -> Result<(), ViscousError> {
        let (sample, courant) = (self.sample, self.courant);
        // A flow at rest: its step from the path's fastest edge; a flow
        // continued from another grid's: from its own.
        let speed_ratio = if flow.time() == 0.0 {
            self.path.peak_speed_ratio()
        } else {
            1.0
        };
        let first = (courant * flow.stable_dt(1.0) / speed_ratio).min(sample);
        self.smallest = self.smallest.min(first);
        let mut control = StepControl::new(first, sample, courant);
        let end = until + 1e-9 * sample;
        let mut taken = 0;
        while self.next <= end {
            if taken % CHECK_EVERY == 0 && taken > 0 {
                control.adjust(flow, self.duration, self.steps)?;
            }
            let dt = control.dt();
            self.smallest = self.smallest.min(dt);
            // The loads (a pass round the wall) only either side of a
            // step that crosses a sample time.
            let before =
                (flow.time() + dt >= self.next - 1e-12).then(|| (flow.time(), coefficients(flow)));
            flow.step(dt).map_err(|e| match e {
                NsError::Diverged { time, step, dt } => ViscousError::Diverged {
                    time,
                    step,
                    dt,
                    courant,
                },
                e => e.into(),
            })?;
            self.steps += 1;
            taken += 1;
            self.frame(flow, frames)?;
            let Some(before) = before else { continue };
            let now = (flow.time(), coefficients(flow));
            let history = &mut self.history;
            while self.next <= now.0 + 1e-12 && self.next <= end {
                let w = (self.next - before.0) / (now.0 - before.0);
                let at = |i: usize| before.1[i] + w * (now.1[i] - before.1[i]);
                history.time.push(self.next);
                history.cl.push(at(0));
                history.ct.push(at(1));
                history.cp.push(at(2));
                history.cd_friction.push(0.0);
                self.next += sample;
            }
            frames.reached(now.0.min(self.duration), self.duration);
        }
        Ok(())
    }
}
