//! A connected flight controller: what `fwav upload`, `fwav fc` and
//! `fwav monitor` do, as functions that return typed results.

use std::io::{Read, Write};

use fwav_protocol::{
    Command, DeviceHello, Limits, ParamId, ParamValue, Profile, ProfileError, Reply, Status,
    TelemetryConfig,
};

use fwav_settings::Shown;

use crate::link::{Link, LinkError};

/// Why an operation on the device failed.
#[derive(Debug, thiserror::Error)]
pub enum DeviceError {
    /// The link failed or the device refused.
    #[error(transparent)]
    Link(#[from] LinkError),
    /// The profile violates the device's limits (checked before sending).
    #[error("the profile exceeds the device's limits:\n  {}", .0.iter().map(ToString::to_string).collect::<Vec<_>>().join("\n  "))]
    OutOfLimits(Vec<ProfileError>),
    /// What the device holds after the upload is not what was sent.
    #[error("read-back differs from the uploaded profile: the device holds {held}")]
    ReadBackDiffers {
        /// What the device reported.
        held: String,
    },
    /// No parameter of that name.
    #[error("no parameter named {name:?}; the parameters are: {}", fwav_protocol::PARAMS.iter().map(|p| p.name).collect::<Vec<_>>().join(", "))]
    UnknownParam {
        /// The name given.
        name: String,
    },
    /// A parameter value outside its range.
    #[error("{name} = {} is outside {}..={} {unit}", Shown(*value), Shown(*min), Shown(*max))]
    ParamOutOfRange {
        /// Parameter name.
        name: &'static str,
        /// Value given (as given: one beyond an `f32`'s range is not shown
        /// as `inf`).
        value: f64,
        /// Smallest allowed, as declared ([`fwav_protocol::ParamInfo::bounds`]).
        min: f64,
        /// Largest allowed, as declared.
        max: f64,
        /// Unit.
        unit: &'static str,
    },
}

/// A flight controller after a successful handshake.
pub struct Device<P> {
    /// The link.
    pub link: Link<P>,
    /// Its handshake answer (firmware name, version).
    pub hello: DeviceHello,
    /// Its kinematic limits.
    pub limits: Limits,
}

impl<P: Read + Write> Device<P> {
    /// Handshakes on `port` and reads the device's limits.
    pub fn connect(port: P) -> Result<Self, DeviceError> {
        let mut link = Link::new(port);
        let hello = link.handshake()?;
        let limits = match link.request(Command::GetLimits)? {
            Reply::Limits(l) => l,
            other => {
                return Err(LinkError::Unexpected {
                    command: "limits",
                    answer: format!("{other:?}"),
                }
                .into());
            }
        };
        Ok(Self {
            link,
            hello,
            limits,
        })
    }

    /// Checks `profile` against the device's limits, uploads it, reads it
    /// back and compares.
    pub fn upload(&mut self, profile: &Profile) -> Result<(), DeviceError> {
        let mut violations = Vec::new();
        profile.for_each_violation(&self.limits, |e| violations.push(e));
        if !violations.is_empty() {
            return Err(DeviceError::OutOfLimits(violations));
        }
        self.link.command(Command::UploadProfile(profile.clone()))?;
        match self.link.request(Command::ReadProfile)? {
            Reply::Profile(Some(held)) if held == *profile => Ok(()),
            other => Err(DeviceError::ReadBackDiffers {
                held: format!("{other:?}"),
            }),
        }
    }

    /// The device's status.
    pub fn status(&mut self) -> Result<Status, DeviceError> {
        match self.link.request(Command::GetStatus)? {
            Reply::Status(s) => Ok(s),
            other => Err(LinkError::Unexpected {
                command: "status",
                answer: format!("{other:?}"),
            }
            .into()),
        }
    }

    /// All parameters.
    pub fn params(&mut self) -> Result<Vec<ParamValue>, DeviceError> {
        match self.link.request(Command::GetParams)? {
            Reply::Params(list) => Ok(list.to_vec()),
            other => Err(LinkError::Unexpected {
                command: "parameters",
                answer: format!("{other:?}"),
            }
            .into()),
        }
    }

    /// Sets a parameter by its command-line name, checked locally first.
    pub fn set_param(&mut self, name: &str, value: f64) -> Result<(), DeviceError> {
        let id = ParamId::from_name(name).ok_or_else(|| DeviceError::UnknownParam {
            name: name.to_owned(),
        })?;
        let info = id.info();
        // The range as declared, in f64, as a plant file's value is
        // checked: 1000.00001 ohm is refused here as there, though its f32
        // rounds to 1000. A value inside it is inside the device's f32
        // range too (rounding keeps the order), and NaN and 1e300 (inf on
        // the wire) are outside. The error shows the value given.
        let [low, high] = info.bounds;
        if !(value >= low && value <= high) {
            return Err(DeviceError::ParamOutOfRange {
                name: info.name,
                value,
                min: info.bounds[0],
                max: info.bounds[1],
                unit: info.unit,
            });
        }
        Ok(self.link.command(Command::SetParam(ParamValue {
            id,
            value: value as f32,
        }))?)
    }

    /// Arms; returns the session whose heartbeats ([`Device::heartbeat`])
    /// alone keep the device armed (status queries do not).
    pub fn arm(&mut self) -> Result<u32, DeviceError> {
        Ok(self.link.arm()?)
    }

    /// The heartbeat of `session` (from [`Device::arm`]), due at least once
    /// per link timeout while armed.
    pub fn heartbeat(&mut self, session: u32) -> Result<(), DeviceError> {
        Ok(self.link.heartbeat(session)?)
    }

    /// Sends one of the simple commands (disarm, start, stop, save, clear
    /// faults; arming is [`Device::arm`]).
    pub fn command(&mut self, command: Command) -> Result<(), DeviceError> {
        Ok(self.link.command(command)?)
    }

    /// Turns the telemetry stream on (one sample every `decimation` control
    /// steps) or off.
    pub fn telemetry(&mut self, enabled: bool, decimation: u16) -> Result<(), DeviceError> {
        self.command(Command::SetTelemetry(TelemetryConfig {
            enabled,
            decimation,
        }))
    }
}
