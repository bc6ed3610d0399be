//! The files a command writes under names its user gave (`--plot FILE`,
//! `--out DIR`'s files): a name that is taken is refused before the run,
//! so that a long run is not lost at its end, and each file is then
//! written only where nothing is ([`fwav::files::create_new`]), so that
//! one made while the run went on is kept too. An existing file is
//! never overwritten.

use std::path::Path;

use anyhow::{bail, Result};
use fwav::files::{check_new, NewFileError};

/// Refuses the first of `files` (`(flag, path)`) that exists, or whose
/// directory does not, naming its flag.
pub fn refuse_taken<'a>(files: impl IntoIterator<Item = (&'a str, &'a Path)>) -> Result<()> {
    for (flag, path) in files {
        match check_new(path) {
            Ok(()) => {}
            Err(NewFileError::Taken(_)) => bail!(
                "{flag} {}: the file exists (an existing file is never overwritten); \
                 choose a new name or remove it",
                path.display()
            ),
            Err(NewFileError::NotADirectory(dir)) => bail!(
                "{flag} {}: {} is not a directory; choose another",
                path.display(),
                dir.display()
            ),
            Err(NewFileError::Directory { dir, source }) => bail!(
                "{flag} {}: its directory {}: {source}; make it first, or choose another",
                path.display(),
                dir.display()
            ),
        }
    }
    Ok(())
}

/// Refuses the output directory `dir` (given to `flag`) if it holds a
/// file the command writes: one of `names`, or one of a numbered series
/// (`series`: each a name's start and end around its number, such as
/// `("wing-", ".vtu")` for `wing-0003.vtu`). A directory that does not
/// exist yet holds none.
pub fn refuse_taken_in(
    flag: &str,
    dir: &Path,
    names: &[&str],
    series: &[(&str, &str)],
) -> Result<()> {
    // A link to a directory is one (metadata follows links).
    if std::fs::metadata(dir).is_ok_and(|m| !m.is_dir()) {
        bail!(
            "{flag} {}: not a directory; name a new directory or an existing one",
            dir.display()
        );
    }
    let entries = match std::fs::read_dir(dir) {
        Ok(entries) => entries,
        // Made by the command.
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
        Err(e) => bail!("{flag} {}: cannot read the directory: {e}", dir.display()),
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let name = name.to_string_lossy();
        let ours = names.contains(&name.as_ref())
            || series
                .iter()
                .any(|(start, end)| numbered(&name, start, end));
        if ours {
            bail!(
                "{flag} {}: {name} is there already (an existing file is never \
                 overwritten); choose another directory, or remove the command's \
                 files from it ({})",
                dir.display(),
                written_names(names, series)
            );
        }
    }
    Ok(())
}

/// Whether `name` is `start`, digits, `end` (`wing-0003.vtu`).
fn numbered(name: &str, start: &str, end: &str) -> bool {
    name.strip_prefix(start)
        .and_then(|rest| rest.strip_suffix(end))
        .is_some_and(|digits| !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()))
}

/// `a.json, b.csv, wing-*.vtu`.
fn written_names(names: &[&str], series: &[(&str, &str)]) -> String {
    let series = series.iter().map(|(start, end)| format!("{start}*{end}"));
    names
        .iter()
        .map(|n| n.to_string())
        .chain(series)
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A numbered series' file is its start, digits and end, and only
    /// that: a user's `wing-mesh.vtu` in the directory is not one.
    #[test]
    fn a_series_file_is_numbered() {
        assert!(numbered("wing-0003.vtu", "wing-", ".vtu"));
        for other in [
            "wing-mesh.vtu",
            "wing-.vtu",
            "wing-3.vtu.bak",
            "wake-0003.vtu",
        ] {
            assert!(!numbered(other, "wing-", ".vtu"), "{other}");
        }
    }
}
