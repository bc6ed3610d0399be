//! A real single-node Slurm cluster on this machine, for the tests of
//! `fwav study --executor slurm`: Debian's `slurm-wlm` and `munge`
//! (installed with apt-get when missing, without the recommended plugin
//! packages; that needs root), a `munged`
//! with its own key and socket, and `slurmctld` and `slurmd` with a
//! generated `slurm.conf` for this host's CPUs and memory (as `slurmd -C`
//! reports them), on free ports, every state, spool, log and pid file in
//! a temporary directory. The three daemons run in the foreground as
//! children of the test and are stopped by their pids when the cluster
//! is dropped (jobs still queued are cancelled first).
//!
//! No accounting storage: `sacct` answers "accounting storage is
//! disabled", and the executor follows the array with `squeue
//! --states=all` (`MinJobAge` keeps ended tasks listed) and the cases'
//! own files, as on a cluster without accounting.

use std::net::TcpListener;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use rustix::process::{kill_process, Pid, Signal};

/// The cluster, until dropped.
pub struct Cluster {
    dir: PathBuf,
    conf: PathBuf,
    daemons: Vec<(&'static str, Child)>,
}

/// The programs the cluster and the executor need.
const PROGRAMS: [&str; 8] = [
    "munged",
    "slurmctld",
    "slurmd",
    "sbatch",
    "squeue",
    "scancel",
    "sinfo",
    "scontrol",
];

/// `program` on PATH or in the system directories (sbin is not on every
/// PATH).
fn find(program: &str) -> Option<PathBuf> {
    let path = std::env::var_os("PATH").unwrap_or_default();
    std::env::split_paths(&path)
        .chain(["/usr/sbin", "/usr/bin", "/sbin", "/bin"].map(PathBuf::from))
        .map(|d| d.join(program))
        .find(|p| p.is_file())
}

/// Installs `slurm-wlm` and `munge` with apt-get if a program is
/// missing; the reason if that cannot be done.
fn install() -> Result<(), String> {
    let missing: Vec<&str> = PROGRAMS.into_iter().filter(|p| find(p).is_none()).collect();
    if missing.is_empty() {
        return Ok(());
    }
    if !rustix::process::geteuid().is_root() {
        return Err(format!(
            "{} not installed, and installing slurm-wlm and munge needs root",
            missing.join(", ")
        ));
    }
    let Some(apt) = find("apt-get") else {
        return Err(format!(
            "{} not installed, and there is no apt-get",
            missing.join(", ")
        ));
    };
    let apt_get = |args: &[&str]| {
        Command::new(&apt)
            .args(args)
            .env("DEBIAN_FRONTEND", "noninteractive")
            .stdin(Stdio::null())
            .output()
    };
    eprintln!("installing slurm-wlm and munge (apt-get) for the Slurm test");
    let packages = [
        "install",
        "-y",
        "-q",
        "--no-install-recommends",
        "slurm-wlm",
        "munge",
    ];
    let first = apt_get(&packages).map_err(|e| format!("apt-get: {e}"))?;
    if !first.status.success() {
        // A fresh machine's package lists may be missing or stale.
        apt_get(&["update", "-q"]).map_err(|e| format!("apt-get update: {e}"))?;
        let again = apt_get(&packages).map_err(|e| format!("apt-get: {e}"))?;
        if !again.status.success() {
            return Err(format!(
                "apt-get install slurm-wlm munge failed: {}",
                String::from_utf8_lossy(&again.stderr).trim()
            ));
        }
    }
    match PROGRAMS.into_iter().find(|p| find(p).is_none()) {
        Some(p) => Err(format!(
            "{p} still missing after installing slurm-wlm and munge"
        )),
        None => Ok(()),
    }
}

/// A TCP port free right now.
fn free_port() -> Result<u16, String> {
    let l = TcpListener::bind("127.0.0.1:0").map_err(|e| format!("a free port: {e}"))?;
    l.local_addr().map(|a| a.port()).map_err(|e| e.to_string())
}

/// Spawns a daemon in the foreground, its output in `log`.
fn spawn(program: &str, args: &[String], log: &Path) -> Result<Child, String> {
    let out = std::fs::File::create(log).map_err(|e| format!("{}: {e}", log.display()))?;
    let err = out.try_clone().map_err(|e| e.to_string())?;
    Command::new(find(program).ok_or(format!("{program} not found"))?)
        .args(args)
        .stdin(Stdio::null())
        .stdout(out)
        .stderr(err)
        .spawn()
        .map_err(|e| format!("starting {program}: {e}"))
}

/// Waits up to `limit` for `ready`.
fn wait_for(limit: Duration, mut ready: impl FnMut() -> bool) -> bool {
    let clock = Instant::now();
    while clock.elapsed() < limit {
        if ready() {
            return true;
        }
        std::thread::sleep(Duration::from_millis(200));
    }
    false
}

impl Cluster {
    /// Installs Slurm if needed and starts the cluster; the reason if it
    /// cannot be (the test then says it skipped its Slurm part).
    pub fn start() -> Result<Self, String> {
        install()?;
        let dir = std::env::temp_dir().join(format!("fwav-slurm-{}", std::process::id()));
        std::fs::remove_dir_all(&dir).ok();
        for sub in ["state", "spool", "log"] {
            std::fs::create_dir_all(dir.join(sub)).map_err(|e| e.to_string())?;
        }
        let mut cluster = Self {
            conf: dir.join("slurm.conf"),
            dir,
            daemons: Vec::new(),
        };
        cluster.start_munge()?;
        cluster.start_slurm()?;
        Ok(cluster)
    }

    /// `munged` with its own key and socket.
    fn start_munge(&mut self) -> Result<(), String> {
        use std::os::unix::fs::PermissionsExt;
        let d = &self.dir;
        let key = d.join("munge.key");
        let mut bytes = vec![0u8; 1024];
        let mut urandom = std::fs::File::open("/dev/urandom").map_err(|e| e.to_string())?;
        std::io::Read::read_exact(&mut urandom, &mut bytes).map_err(|e| e.to_string())?;
        std::fs::write(&key, bytes).map_err(|e| e.to_string())?;
        std::fs::set_permissions(&key, std::fs::Permissions::from_mode(0o600))
            .map_err(|e| e.to_string())?;
        std::fs::set_permissions(d, std::fs::Permissions::from_mode(0o755))
            .map_err(|e| e.to_string())?;
        let socket = d.join("munge.socket");
        let arg = |name: &str, p: PathBuf| format!("--{name}={}", p.display());
        let args = vec![
            "--foreground".to_string(),
            "--force".to_string(),
            arg("socket", socket.clone()),
            arg("key-file", key),
            arg("pid-file", d.join("munged.pid")),
            arg("log-file", d.join("log/munged.log")),
            arg("seed-file", d.join("munged.seed")),
        ];
        let child = spawn("munged", &args, &d.join("log/munged.out"))?;
        self.daemons.push(("munged", child));
        if !wait_for(Duration::from_secs(10), || socket.exists()) {
            return Err(format!("munged did not start: {}", self.log("munged.out")));
        }
        Ok(())
    }

    /// `slurm.conf` for this host, `slurmctld` and `slurmd`, and the wait
    /// for the node to be idle.
    fn start_slurm(&mut self) -> Result<(), String> {
        let d = self.dir.display().to_string();
        let node = Command::new(find("slurmd").ok_or("slurmd not found")?)
            .arg("-C")
            .output()
            .map_err(|e| format!("slurmd -C: {e}"))?;
        let node = String::from_utf8_lossy(&node.stdout);
        let node = node
            .lines()
            .find(|l| l.starts_with("NodeName="))
            .ok_or(format!("slurmd -C gave no node line: {node}"))?;
        let host = node
            .split_whitespace()
            .next()
            .and_then(|w| w.strip_prefix("NodeName="))
            .ok_or("no node name")?
            .to_string();
        let conf = format!(
            "ClusterName=fwavtest\n\
             SlurmctldHost={host}(127.0.0.1)\n\
             SlurmUser=root\nSlurmdUser=root\n\
             SlurmctldPort={}\nSlurmdPort={}\n\
             AuthType=auth/munge\nCredType=cred/munge\nAuthInfo=socket={d}/munge.socket\n\
             StateSaveLocation={d}/state\nSlurmdSpoolDir={d}/spool\n\
             SlurmctldPidFile={d}/slurmctld.pid\nSlurmdPidFile={d}/slurmd.pid\n\
             SlurmctldLogFile={d}/log/slurmctld.log\nSlurmdLogFile={d}/log/slurmd.log\n\
             ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n\
             JobAcctGatherType=jobacct_gather/none\nAccountingStorageType=accounting_storage/none\n\
             JobCompType=jobcomp/none\nMpiDefault=none\nSwitchType=switch/none\n\
             SchedulerType=sched/backfill\nSelectType=select/cons_tres\nSelectTypeParameters=CR_CPU\n\
             ReturnToService=2\nMinJobAge=600\nKillWait=5\n\
             {node} NodeAddr=127.0.0.1 State=UNKNOWN\n\
             PartitionName=test Nodes={host} Default=YES MaxTime=INFINITE State=UP\n",
            free_port()?,
            free_port()?,
        );
        std::fs::write(&self.conf, conf).map_err(|e| e.to_string())?;
        let args = vec![
            "-D".to_string(),
            "-f".to_string(),
            self.conf.display().to_string(),
        ];
        let ctld = spawn("slurmctld", &args, &self.dir.join("log/slurmctld.out"))?;
        self.daemons.push(("slurmctld", ctld));
        let slurmd = spawn("slurmd", &args, &self.dir.join("log/slurmd.out"))?;
        self.daemons.push(("slurmd", slurmd));
        let idle = wait_for(Duration::from_secs(30), || {
            self.command("sinfo")
                .args(["--noheader", "--format=%T"])
                .output()
                .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "idle")
        });
        if !idle {
            return Err(format!(
                "the node did not come up idle: {} {}",
                self.log("slurmctld.out"),
                self.log("slurmd.out")
            ));
        }
        Ok(())
    }

    /// The last lines of a log of the cluster.
    fn log(&self, name: &str) -> String {
        let text = std::fs::read_to_string(self.dir.join("log").join(name)).unwrap_or_default();
        let lines: Vec<&str> = text.lines().collect();
        lines[lines.len().saturating_sub(5)..].join(" | ")
    }

    /// `SLURM_CONF` for the clients (`sbatch`, `squeue`, ...) of this
    /// cluster.
    pub fn conf(&self) -> &Path {
        &self.conf
    }

    /// A Slurm client command of this cluster.
    pub fn command(&self, program: &str) -> Command {
        let mut c = Command::new(find(program).unwrap_or_else(|| PathBuf::from(program)));
        c.env("SLURM_CONF", &self.conf);
        c
    }

    /// Every job the controller holds (ended ones too, for `MinJobAge`),
    /// as `squeue --states=all` lists them.
    pub fn jobs(&self) -> Vec<String> {
        let out = self
            .command("squeue")
            .args(["--noheader", "--states=all", "--format=%i %T"])
            .output()
            .expect("squeue runs");
        String::from_utf8_lossy(&out.stdout)
            .lines()
            .map(str::to_string)
            .collect()
    }
}

impl Drop for Cluster {
    /// Cancels what is still queued, then stops the daemons by their
    /// pids (SIGTERM, then SIGKILL after 10 s) and removes the directory.
    fn drop(&mut self) {
        let queued = || {
            self.command("squeue")
                .args(["--noheader", "--format=%A"])
                .output()
                .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
                .unwrap_or_default()
        };
        for job in queued().lines() {
            let _ = self.command("scancel").arg(job.trim()).status();
        }
        wait_for(Duration::from_secs(20), || queued().is_empty());
        for (name, child) in self.daemons.iter_mut().rev() {
            let pid = i32::try_from(child.id()).ok().and_then(Pid::from_raw);
            if let Some(pid) = pid {
                let _ = kill_process(pid, Signal::TERM);
            }
            let ended = wait_for(Duration::from_secs(10), || {
                child.try_wait().is_ok_and(|s| s.is_some())
            });
            if !ended {
                eprintln!("{name} ignored SIGTERM: killing it");
                let _ = child.kill();
                let _ = child.wait();
            }
        }
        std::fs::remove_dir_all(&self.dir).ok();
    }
}
