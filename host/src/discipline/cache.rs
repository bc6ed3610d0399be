//! Evaluations keyed by their inputs, so a rerun (or a resumed design
//! run) reuses every 2D analysis already done. The key is a 64-bit FNV-1a
//! hash of the evaluation's inputs serialized as JSON (the section case and
//! the design, in Hz and degrees as [`FlappingKinematics`] writes them), stable across runs and platforms; the file is JSON,
//! written atomically.
//!
//! The case is keyed as its model reads it ([`SectionCase::modelled`]):
//! the flow model and its plate and grid are part of the key (an LDVM
//! result is never served for a Navier–Stokes request, nor one grid's for
//! another's, nor one deformation's for another's). Each case carries the
//! revision of its model's results ([`LDVM_RESULTS_REVISION`],
//! [`NS_RESULTS_REVISION`]), so results the model no longer gives are not
//! served.
//!
//! A cache kept in a file ([`EvaluationCache::kept_in`], as `fwav design`
//! and `fwav kinematics --cache` keep theirs) writes the file again at
//! every new result, so a run killed in the middle of a discipline loses
//! only the evaluations still running: a Navier–Stokes discipline is some
//! twenty evaluations of two to three minutes each, and before, a kill
//! lost them all.
//!
//! Several processes may keep their caches in one file (two `fwav
//! kinematics --cache` runs at once, say): each write, under a lock of the
//! file `FILE.lock` beside it, adds the results the file already holds, so
//! none is lost and the file is never a mix of two writes
//! ([`EvaluationCache::save`]).

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use serde::{Deserialize, Serialize};

use crate::aeroelastic::kinematics::FlappingKinematics;

use super::section::{SectionCase, SectionResult};
use super::section_model::SectionFlowModel;

/// Why the cache file could not be read or written.
#[derive(Debug, thiserror::Error)]
pub enum CacheError {
    /// Reading or writing the file.
    #[error("evaluation cache {path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// Cause.
        source: std::io::Error,
    },
    /// Writing the file.
    #[error("evaluation cache: {0}")]
    Write(#[from] crate::files::WriteError),
    /// Another of the program's files (its `format` names another kind).
    #[error(
        "evaluation cache {path}: a {format:?} file, not an evaluation cache ({FORMAT:?}): \
         give another file name, or a missing one to start a new cache"
    )]
    OtherKind {
        /// The file.
        path: String,
        /// The `format` it names.
        format: String,
    },
    /// Not a cache file.
    #[error("evaluation cache {path}: {message}")]
    Format {
        /// The file.
        path: String,
        /// What is wrong.
        message: String,
    },
}

/// Finished evaluations by key.
#[derive(Debug, Default)]
pub struct EvaluationCache {
    entries: Mutex<HashMap<String, SectionResult>>,
    /// The file every new result is written to at once ([`Self::kept_in`]).
    file: Option<PathBuf>,
    /// Held while a file is written, so that writes never interleave and
    /// the last one holds every result.
    writing: Mutex<()>,
}

#[derive(Serialize, Deserialize)]
struct CacheFile {
    format: String,
    entries: HashMap<String, SectionResult>,
}

const FORMAT: &str = "fwav-evaluations-2";

/// The `format` key of any of the program's JSON files, the rest ignored.
#[derive(Deserialize)]
struct Kind {
    format: Option<String>,
}

impl EvaluationCache {
    /// An empty cache.
    pub fn new() -> Self {
        Self::default()
    }

    /// Loads `path`; a missing file is an empty cache.
    pub fn load(path: &Path) -> Result<Self, CacheError> {
        Ok(Self {
            entries: Mutex::new(read_entries(path)?),
            ..Self::default()
        })
    }

    /// Loads `path` as [`Self::load`] does, and keeps the cache in it:
    /// every [`Self::insert`] writes the file again (atomically; a design
    /// run's few hundred results are tens of kilobytes), so the results
    /// survive a kill, with the results other processes wrote to it in
    /// the meantime added ([`Self::save`]).
    pub fn kept_in(path: &Path) -> Result<Self, CacheError> {
        Ok(Self {
            file: Some(path.to_path_buf()),
            ..Self::load(path)?
        })
    }

    /// Writes the cache to `path` atomically, with the results already in
    /// the file added. For a cache kept in a file this is the check that
    /// every result reached it: an insert's failed write is not an error
    /// until here.
    ///
    /// Other processes may keep their caches in the same file (two `fwav
    /// kinematics --cache` runs, say): under an exclusive lock of
    /// `path.lock` the results the file holds are first added to this
    /// cache's, so that each write keeps every process's results, and no
    /// two writes interleave. (Before, the last writer's results replaced
    /// the others', and two writes at once could leave a file mixed of
    /// both.) A file that is no longer a cache is not overwritten: the
    /// write fails, naming it. Cost: reading and parsing the file, tens of
    /// kilobytes, at each write.
    pub fn save(&self, path: &Path) -> Result<(), CacheError> {
        let _writing = self
            .writing
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        self.write(path)
    }

    /// Writes every result to `path` as [`Self::save`] says; the caller
    /// holds `writing`.
    fn write(&self, path: &Path) -> Result<(), CacheError> {
        let _lock = lock_file(path)?;
        let on_disk = read_entries(path)?;
        let entries = {
            let mut entries = self.lock();
            for (key, result) in on_disk {
                entries.entry(key).or_insert(result);
            }
            entries.clone()
        };
        let text = serde_json::to_string(&CacheFile {
            format: FORMAT.to_string(),
            entries,
        })
        .map_err(|e| CacheError::Format {
            path: path.display().to_string(),
            message: e.to_string(),
        })?;
        Ok(crate::files::write_atomic_to(path, text)?)
    }

    /// Number of stored evaluations.
    pub fn len(&self) -> usize {
        self.lock().len()
    }

    /// The keys of the stored evaluations ([`key`]), as they are now.
    pub fn keys(&self) -> std::collections::HashSet<String> {
        self.lock().keys().cloned().collect()
    }

    /// Whether nothing is stored.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The stored result for these inputs, if any.
    pub fn get(&self, case: &SectionCase, design: &FlappingKinematics) -> Option<SectionResult> {
        self.lock().get(&key(case, design)).copied()
    }

    /// Stores a result, and for a cache kept in a file writes the file.
    /// A failed write does not lose the result: it stays in memory, the
    /// next insert writes it again, and [`Self::save`] reports the failure
    /// if it persists.
    pub fn insert(&self, case: &SectionCase, design: &FlappingKinematics, result: SectionResult) {
        self.lock().insert(key(case, design), result);
        if let Some(path) = &self.file {
            let _writing = self
                .writing
                .lock()
                .unwrap_or_else(std::sync::PoisonError::into_inner);
            // Not lost on failure: kept in memory, written by the next
            // insert, and reported by `save` if the file stays unwritable.
            let _ = self.write(path);
        }
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, HashMap<String, SectionResult>> {
        // A panic while holding the lock cannot leave the map half
        // written (single inserts), so a poisoned lock is still usable.
        self.entries.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// The results in the cache file `path`; a missing file has none.
fn read_entries(path: &Path) -> Result<HashMap<String, SectionResult>, CacheError> {
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(HashMap::new()),
        Err(source) => {
            return Err(CacheError::Io {
                path: path.display().to_string(),
                source,
            })
        }
    };
    // The kind of file first: another of the program's files (a
    // `system.json` given as the cache) is named as what it is, not by
    // the key of a cache it lacks.
    if let Ok(Kind {
        format: Some(format),
    }) = serde_json::from_str::<Kind>(&text)
    {
        if !format.starts_with("fwav-evaluations") {
            return Err(CacheError::OtherKind {
                path: path.display().to_string(),
                format,
            });
        }
    }
    let file: CacheFile = serde_json::from_str(&text).map_err(|e| CacheError::Format {
        path: path.display().to_string(),
        message: e.to_string(),
    })?;
    if file.format != FORMAT {
        return Err(CacheError::Format {
            path: path.display().to_string(),
            message: format!(
                "format {:?}, expected {FORMAT:?} (results of an older version: delete the file to recompute)",
                file.format
            ),
        });
    }
    Ok(file.entries)
}

/// The exclusive lock of the cache file `path`: an advisory `flock` of the
/// empty file `path.lock` beside it, created if missing and left in place
/// (removing it while another process waits on it would let two writers
/// in). The kernel releases the lock when the returned file is dropped, or
/// its process ends however it ends. Blocks while another writer holds it:
/// a write takes milliseconds, but a writer stopped mid-write (Ctrl-Z)
/// holds the others until it goes on. On NFS, where Linux emulates
/// `flock` by POSIX locks, two caches of one process do not exclude each
/// other (two processes still do).
fn lock_file(path: &Path) -> Result<std::fs::File, CacheError> {
    let mut name = path.as_os_str().to_owned();
    name.push(".lock");
    let lock_path = PathBuf::from(name);
    let error = |source| CacheError::Io {
        path: lock_path.display().to_string(),
        source,
    };
    let file = std::fs::OpenOptions::new()
        .create(true)
        .truncate(false)
        .write(true)
        .open(&lock_path)
        .map_err(error)?;
    rustix::fs::flock(&file, rustix::fs::FlockOperation::LockExclusive)
        .map_err(|e| error(e.into()))?;
    Ok(file)
}

/// The revision of the Navier–Stokes model's results, part of its keys:
/// raised when the same inputs give other results, so that a cache file
/// never serves the former ones. 2 (2026-12-04): the input power counts
/// the section's motion relative to steady flight only (before, the
/// flight's `-T U` too: `aero2d/viscous/march.rs`).
pub const NS_RESULTS_REVISION: u32 = 2;

/// The revision of the LDVM's results, part of its keys (as
/// [`NS_RESULTS_REVISION`]; until it, an LDVM key held its inputs alone).
/// 1 (2026-12-07): a deforming section's share of the unsteady pressure
/// at the half step, and the newest wake vortex placed and seen by the
/// chord so that the loads converge at first order in the step
/// (`aero2d/ldvm.rs`, "The wake next to the edge"): the built-in
/// design's L18 rows' power moved by 5.8 % on average, 9.3 % at most.
pub const LDVM_RESULTS_REVISION: u32 = 1;

/// The key of an evaluation: FNV-1a of its inputs' JSON (the case as its
/// model reads it, with its model's results revision:
/// [`LDVM_RESULTS_REVISION`], [`NS_RESULTS_REVISION`]), hex.
pub fn key(case: &SectionCase, design: &FlappingKinematics) -> String {
    let mut inputs = serde_json::json!({ "case": case.modelled(), "design": design });
    match case.model {
        SectionFlowModel::Ldvm => inputs["ldvm_results"] = LDVM_RESULTS_REVISION.into(),
        SectionFlowModel::Ns(_) => inputs["ns_results"] = NS_RESULTS_REVISION.into(),
    }
    fnv1a(&inputs.to_string())
}

/// The 64-bit FNV-1a hash of `text`, hex.
fn fnv1a(text: &str) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in text.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    format!("{h:016x}")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each model's keys carry its results' revision: a Navier–Stokes
    /// result of the former input power, or an LDVM result from before
    /// its edge placement (whose key was its inputs alone), is not
    /// served; and an LDVM key is not a Navier–Stokes one.
    #[test]
    fn keys_carry_their_models_results_revision() {
        let design = FlappingKinematics::from_degrees([11.0, 30.0, 0.0, 90.0]);
        let ldvm = SectionCase::fwav_mid_span();
        let ns = SectionCase {
            model: SectionFlowModel::ns(0.04),
            ..SectionCase::fwav_mid_span()
        };
        let unrevised = |case: &SectionCase| {
            fnv1a(&serde_json::json!({ "case": case.modelled(), "design": design }).to_string())
        };
        assert_ne!(key(&ldvm, &design), unrevised(&ldvm));
        assert_ne!(key(&ns, &design), unrevised(&ns));
        assert_ne!(key(&ldvm, &design), key(&ns, &design));
    }

    /// A fresh, empty directory for one test.
    fn scratch(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("fwav-cache-{name}-{}", std::process::id()));
        std::fs::remove_dir_all(&dir).ok();
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn result(ct: f64) -> SectionResult {
        SectionResult {
            reduced_frequency: 0.69,
            ct,
            ct_net: ct,
            cp: 2.6,
            efficiency: ct / 2.6,
            efficiency_net: ct / 2.6,
            ct_change: 0.0,
        }
    }

    /// A cache kept in a file has every result on disk the moment it is
    /// inserted (what a killed design run finds when resumed), and a
    /// fresh load serves them; `load` alone keeps the file untouched.
    #[test]
    fn a_kept_cache_writes_each_result_at_once() {
        let dir = scratch("kept");
        let path = dir.join("evaluations.json");
        let case = SectionCase::fwav_mid_span();
        let designs = [
            FlappingKinematics::from_degrees([11.0, 30.0, 0.0, 90.0]),
            FlappingKinematics::from_degrees([9.0, 20.0, -10.0, 70.0]),
        ];
        let kept = EvaluationCache::kept_in(&path).unwrap();
        assert!(kept.is_empty() && !path.exists());
        kept.insert(&case, &designs[0], result(0.09));
        let on_disk = EvaluationCache::load(&path).unwrap();
        assert_eq!(on_disk.get(&case, &designs[0]), Some(result(0.09)));
        kept.insert(&case, &designs[1], result(0.03));
        let on_disk = EvaluationCache::load(&path).unwrap();
        assert_eq!(on_disk.len(), 2);
        assert_eq!(on_disk.get(&case, &designs[1]), Some(result(0.03)));
        assert!(!dir.join("evaluations.json.partial").exists());
        // Loaded without keeping: inserts stay in memory.
        let before = std::fs::read_to_string(&path).unwrap();
        let loaded = EvaluationCache::load(&path).unwrap();
        loaded.insert(
            &case,
            &FlappingKinematics::from_degrees([13.0, 40.0, 10.0, 110.0]),
            result(0.15),
        );
        assert_eq!(std::fs::read_to_string(&path).unwrap(), before);
        std::fs::remove_dir_all(&dir).ok();
    }

    /// Two caches kept in one file, as two processes keep theirs (each
    /// its own open file, so the lock between them is the kernel's, as
    /// between processes), inserting at once: the file ends with every
    /// result of both, and each cache has gathered the other's after its
    /// save. Before the writes merged, the last writer's results replaced
    /// the other's.
    #[test]
    fn caches_kept_in_one_file_keep_each_others_results() {
        let dir = scratch("shared");
        let path = dir.join("evaluations.json");
        let case = SectionCase::fwav_mid_span();
        let design = |run: usize, i: usize| {
            FlappingKinematics::from_degrees([5.0 + run as f64, 10.0 + i as f64, 0.0, 90.0])
        };
        let caches: Vec<EvaluationCache> = (0..2)
            .map(|_| EvaluationCache::kept_in(&path).unwrap())
            .collect();
        std::thread::scope(|s| {
            for (run, cache) in caches.iter().enumerate() {
                let case = &case;
                s.spawn(move || {
                    for i in 0..40 {
                        cache.insert(case, &design(run, i), result(0.001 * i as f64));
                    }
                });
            }
        });
        let on_disk = EvaluationCache::load(&path).unwrap();
        assert_eq!(on_disk.len(), 80);
        for run in 0..2 {
            for i in [0, 17, 39] {
                assert_eq!(
                    on_disk.get(&case, &design(run, i)),
                    Some(result(0.001 * i as f64))
                );
            }
        }
        for cache in &caches {
            cache.save(&path).unwrap();
            assert_eq!(cache.len(), 80);
        }
        assert!(!dir.join("evaluations.json.partial").exists());
        std::fs::remove_dir_all(&dir).ok();
    }

    /// A file that is no longer a cache (a person's file put in its place)
    /// is not overwritten by a kept cache's writes: the result stays in
    /// memory and `save` names the file and what is wrong with it.
    #[test]
    fn a_kept_cache_leaves_a_file_that_is_not_a_cache() {
        let dir = scratch("replaced");
        let path = dir.join("evaluations.json");
        let kept = EvaluationCache::kept_in(&path).unwrap();
        std::fs::write(&path, "my notes").unwrap();
        let case = SectionCase::fwav_mid_span();
        let design = FlappingKinematics::from_degrees([11.0, 30.0, 0.0, 90.0]);
        kept.insert(&case, &design, result(0.09));
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "my notes");
        assert_eq!(kept.get(&case, &design), Some(result(0.09)));
        let e = kept.save(&path).unwrap_err();
        assert!(matches!(e, CacheError::Format { .. }), "{e:?}");
        assert!(e.to_string().contains("evaluations.json"), "{e}");
        std::fs::remove_dir_all(&dir).ok();
    }

    /// Another of the program's files given as the cache is named as what
    /// it is: a `system.json` was refused for a "missing field `entries`
    /// at line 1 column 16443".
    #[test]
    fn another_kind_of_file_is_named_as_what_it_is() {
        let dir = scratch("other-kind");
        let path = dir.join("system.json");
        std::fs::write(
            &path,
            r#"{"format":"fwav-system-analysis","format_version":1}"#,
        )
        .unwrap();
        let e = EvaluationCache::load(&path).unwrap_err();
        assert!(matches!(e, CacheError::OtherKind { .. }), "{e:?}");
        assert!(
            e.to_string().contains(
                "a \"fwav-system-analysis\" file, not an evaluation cache (\"fwav-evaluations-2\")"
            ),
            "{e}"
        );
        std::fs::write(&path, r#"{"format":"fwav-evaluations-1","entries":{}}"#).unwrap();
        let e = EvaluationCache::load(&path).unwrap_err();
        assert!(e.to_string().contains("an older version"), "{e}");
        std::fs::remove_dir_all(&dir).ok();
    }

    /// A kept cache whose file cannot be written keeps the result in
    /// memory (the evaluation is not lost, nor the run stopped), and
    /// `save`, the run's last write, reports the file.
    #[test]
    fn a_kept_cache_that_cannot_write_reports_at_save() {
        let path = std::env::temp_dir()
            .join(format!("fwav-cache-missing-{}", std::process::id()))
            .join("evaluations.json");
        let kept = EvaluationCache::kept_in(&path).unwrap();
        let case = SectionCase::fwav_mid_span();
        let design = FlappingKinematics::from_degrees([11.0, 30.0, 0.0, 90.0]);
        kept.insert(&case, &design, result(0.09));
        assert_eq!(kept.get(&case, &design), Some(result(0.09)));
        let e = kept.save(&path).unwrap_err();
        assert!(matches!(e, CacheError::Io { .. }), "{e:?}");
        assert!(e.to_string().contains("evaluations.json"), "{e}");
    }
}
