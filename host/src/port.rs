//! Serial ports: opening one with errors a user can act on, and listing
//! them.

use std::time::Duration;

/// Link baud rate (the firmware's UART; USB CDC ignores it).
pub const BAUD: u32 = 460_800;

/// Why a port could not be opened.
#[derive(Debug, thiserror::Error)]
pub enum PortError {
    /// No such device.
    #[error("no such port: {0} (see `fwav ports`)")]
    NoSuchPort(String),
    /// Permission denied.
    #[error("permission denied on {0}: add yourself to the group owning it (usually `sudo usermod -aG dialout $USER`, then log in again)")]
    PermissionDenied(String),
    /// Another program holds it.
    #[error(
        "{0} is busy: another program (a serial monitor, ModemManager, another fwav) has it open"
    )]
    Busy(String),
    /// Anything else.
    #[error("cannot open {port}: {message}")]
    Other {
        /// The port.
        port: String,
        /// The system's message.
        message: String,
    },
}

/// Opens `path` for the fwav link with a short read timeout.
pub fn open(path: &str) -> Result<Box<dyn serialport::SerialPort>, PortError> {
    match serialport::new(path, BAUD)
        .timeout(Duration::from_millis(20))
        .open()
    {
        Ok(port) => Ok(port),
        Err(e) => Err(classify(path, &e)),
    }
}

fn classify(path: &str, e: &serialport::Error) -> PortError {
    let message = e.to_string();
    let lower = message.to_lowercase();
    let exists = std::path::Path::new(path).exists();
    match e.kind() {
        // serialport reports EBUSY (another program holds the port
        // exclusively) and lock failures as NoDevice.
        serialport::ErrorKind::NoDevice if exists => PortError::Busy(path.to_owned()),
        serialport::ErrorKind::NoDevice => PortError::NoSuchPort(path.to_owned()),
        serialport::ErrorKind::Io(std::io::ErrorKind::NotFound) => {
            PortError::NoSuchPort(path.to_owned())
        }
        serialport::ErrorKind::Io(std::io::ErrorKind::PermissionDenied) => {
            PortError::PermissionDenied(path.to_owned())
        }
        _ if lower.contains("no such file") => PortError::NoSuchPort(path.to_owned()),
        _ if lower.contains("permission denied") => PortError::PermissionDenied(path.to_owned()),
        _ if lower.contains("busy") => PortError::Busy(path.to_owned()),
        _ => PortError::Other {
            port: path.to_owned(),
            message,
        },
    }
}

/// A serial port present on this machine.
#[derive(Clone, Debug, serde::Serialize)]
pub struct PortInfo {
    /// Device path.
    pub path: String,
    /// USB vendor:product ids, if a USB device.
    pub usb_id: Option<String>,
    /// USB manufacturer and product strings, if known.
    pub description: Option<String>,
}

/// The serial ports the system lists (pseudo-terminals such as hil-sim's
/// are not listed: give their path directly).
pub fn list() -> Vec<PortInfo> {
    serialport::available_ports()
        .unwrap_or_default()
        .into_iter()
        .map(|p| {
            let (usb_id, description) = match p.port_type {
                serialport::SerialPortType::UsbPort(u) => (
                    Some(format!("{:04x}:{:04x}", u.vid, u.pid)),
                    match (u.manufacturer, u.product) {
                        (Some(m), Some(p)) => Some(format!("{m} {p}")),
                        (m, p) => m.or(p),
                    },
                ),
                _ => (None, None),
            };
            PortInfo {
                path: p.port_name,
                usb_id,
                description,
            }
        })
        .collect()
}
