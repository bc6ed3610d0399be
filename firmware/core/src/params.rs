//! The controller's parameter values, indexed by [`ParamId`], each kept
//! within the range of its [`fwav_protocol::ParamInfo`].

use fwav_protocol::{NackReason, ParamId, ParamValue, MAX_PARAMS, PARAMS};

/// One value per parameter, always within range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParamSet {
    values: [f32; PARAMS.len()],
}

impl Default for ParamSet {
    fn default() -> Self {
        Self::DEFAULT
    }
}

impl ParamSet {
    /// Every parameter at its default.
    pub const DEFAULT: Self = {
        let mut values = [0.0; PARAMS.len()];
        let mut i = 0;
        while i < PARAMS.len() {
            values[i] = PARAMS[i].default;
            i += 1;
        }
        Self { values }
    };

    /// The value of `id`.
    pub fn get(&self, id: ParamId) -> f32 {
        self.values[id as usize]
    }

    /// Sets `id` if `value` is within its range (NaN never is).
    pub fn set(&mut self, id: ParamId, value: f32) -> Result<(), NackReason> {
        if !id.accepts(value) {
            let info = id.info();
            return Err(NackReason::ParamOutOfRange {
                id,
                value,
                min: info.min(),
                max: info.max(),
            });
        }
        self.values[id as usize] = value;
        Ok(())
    }

    /// All values, in wire-id order.
    pub fn to_list(&self) -> heapless::Vec<ParamValue, MAX_PARAMS> {
        PARAMS
            .iter()
            .map(|p| ParamValue {
                id: p.id,
                value: self.get(p.id),
            })
            .collect()
    }

    /// Defaults overwritten by every in-range value of `list`; returns the
    /// set and how many entries were refused.
    pub fn from_list(list: &[ParamValue]) -> (Self, usize) {
        let mut set = Self::DEFAULT;
        let refused = list
            .iter()
            .filter(|p| set.set(p.id, p.value).is_err())
            .count();
        (set, refused)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_round_trip_and_ranges_hold() {
        let p = ParamSet::DEFAULT;
        assert_eq!(ParamSet::from_list(&p.to_list()), (p, 0));
        let mut q = p;
        assert!(matches!(
            q.set(ParamId::CurrentLimit, -1.0),
            Err(NackReason::ParamOutOfRange {
                id: ParamId::CurrentLimit,
                ..
            })
        ));
        assert!(q.set(ParamId::CurrentLimit, f32::NAN).is_err());
        assert_eq!(q, p, "a refused value changes nothing");
        q.set(ParamId::CurrentLimit, 2.0).unwrap();
        assert_eq!(q.get(ParamId::CurrentLimit), 2.0);
        let bad = [ParamValue {
            id: ParamId::GearRatio,
            value: 0.0,
        }];
        assert_eq!(ParamSet::from_list(&bad), (p, 1));
    }
}
