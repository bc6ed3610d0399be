//! Results printed but doubtful: the program says why on standard error,
//! after the results, and exits with status 2 (`main` turns a
//! [`Doubtful`] error into that).

/// The results were printed, but they are doubtful (a run that is not
/// periodic, a wing that left its model's range): why, one line each.
#[derive(Debug, thiserror::Error)]
#[error("{}", .0.join("\nwarning: "))]
pub struct Doubtful(pub Vec<String>);
