//! Timing statistics of a repeated piece of work (a control step, a link
//! frame): count, total, largest, in timer 0 counts
//! ([`crate::counter`]).

/// The spans measured so far.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Cost {
    /// Spans measured.
    pub count: u32,
    /// Their sum, counts.
    pub total: u64,
    /// The longest, counts.
    pub max: u32,
}

impl Cost {
    /// No spans yet.
    pub const NONE: Cost = Cost {
        count: 0,
        total: 0,
        max: 0,
    };

    /// Adds one span of `counts`.
    pub fn record(&mut self, counts: u32) {
        self.count = self.count.saturating_add(1);
        self.total += u64::from(counts);
        self.max = self.max.max(counts);
    }

    /// Mean span in nanoseconds of virtual time (0 without spans).
    pub fn mean_ns(&self) -> u64 {
        if self.count == 0 {
            return 0;
        }
        crate::counter::nanoseconds(self.total) / u64::from(self.count)
    }

    /// Longest span in nanoseconds of virtual time.
    pub fn max_ns(&self) -> u64 {
        crate::counter::nanoseconds(u64::from(self.max))
    }
}
