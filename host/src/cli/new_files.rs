//! The files a command writes under names its user gave (`--plot FILE`,
//! `--out DIR`'s files): a name that is taken is refused before the run,
//! so that a long run is not lost at its end, and each file is then
//! written only where nothing is ([`fwav::files::create_new`]), so that
//! one made while the run went on is kept too. An existing file is
//! never overwritten.

use std::path::Path;

use anyhow::{bail, Result};

/// Refuses the first of `files` (`(flag, path)`) that exists, naming
/// its flag.
pub fn refuse_taken<'a>(files: impl IntoIterator<Item = (&'a str, &'a Path)>) -> Result<()> {
    for (flag, path) in files {
        if std::fs::symlink_metadata(path).is_ok() {
            bail!(
                "{flag} {}: the file exists (an existing file is never overwritten); \
                 choose a new name or remove it",
                path.display()
            );
        }
    }
    Ok(())
}

/// Refuses the output directory `dir` (given to `flag`) if it holds a
/// file the command writes: one of `names`, or one of a numbered series
/// (`series`: each a name's start and end, such as `("wing-", ".vtu")`).
/// A directory that does not exist yet holds none.
pub fn refuse_taken_in(
    flag: &str,
    dir: &Path,
    names: &[&str],
    series: &[(&str, &str)],
) -> Result<()> {
    if std::fs::symlink_metadata(dir).is_ok_and(|m| !m.is_dir()) {
        bail!(
            "{flag} {}: not a directory; name a new directory or an existing one",
            dir.display()
        );
    }
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Ok(());
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let name = name.to_string_lossy();
        let ours = names.contains(&name.as_ref())
            || series
                .iter()
                .any(|(start, end)| name.starts_with(start) && name.ends_with(end));
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
