//! Real-time scheduling of the timed replay loop (`hil-sim replay --realtime`, asked for by
//! default).
//!
//! A HIL rig runs its bearing loop as a real-time thread on a core of its own. What a process
//! can do for itself on Linux is done here for the duration of the timed loop only: the
//! `SCHED_FIFO` policy at a priority (no ordinary process preempts the loop), one CPU (no
//! migration between cores, warm caches), and memory locked (no page fault inside a step).
//! The accuracy pass afterwards runs under the ordinary policy again, on every CPU.
//!
//! What it cannot remove is the kernel's own timer tick and, on a virtual machine, the
//! hypervisor: a step that a tick lands in is longer by the tick's cost. That needs a core
//! isolated at boot (`isolcpus=`, `nohz_full=`), which the report cannot check.

use serde::Serialize;

/// What `--realtime` asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Realtime {
    /// The CPU the timed loop is pinned to.
    pub cpu: usize,
    /// `SCHED_FIFO` priority (1–99).
    pub priority: i32,
}

impl Realtime {
    /// The last CPU the process may run on (the first usually takes the most interrupts), at
    /// priority 80 (above the kernel's threaded interrupts' default 50).
    pub fn default_for_this_machine() -> Self {
        let cpus = std::thread::available_parallelism().map_or(1, usize::from);
        Self {
            cpu: cpus.saturating_sub(1),
            priority: 80,
        }
    }

    /// Whether the request itself is valid: a CPU this process may use and a priority in
    /// `SCHED_FIFO`'s range (1–99 on Linux). A bad request is the user's error in every
    /// `--realtime` mode; only the system's refusal of a valid one lets `auto` fall back.
    pub fn check(&self) -> Result<(), String> {
        let cpus = std::thread::available_parallelism().map_or(1, usize::from);
        // 1024: glibc's CPU_SETSIZE, the CPUs a `cpu_set_t` can name.
        if self.cpu >= cpus || self.cpu >= 1024 {
            return Err(format!(
                "--rt-cpu {} does not exist: this process may use CPUs 0 … {}",
                self.cpu,
                cpus.saturating_sub(1)
            ));
        }
        if !(1..=99).contains(&self.priority) {
            return Err(format!(
                "--rt-priority {} is outside SCHED_FIFO's 1 … 99",
                self.priority
            ));
        }
        Ok(())
    }
}

/// The thread's scheduling while the guard lives; the previous policy, priority and CPU set
/// are restored when it is dropped.
#[derive(Debug)]
pub struct Guard {
    #[cfg(target_os = "linux")]
    previous: linux::Saved,
}

#[cfg(target_os = "linux")]
impl Guard {
    /// Enter real-time scheduling, or say why not (typically: not root and no CAP_SYS_NICE).
    pub fn enter(request: Realtime) -> Result<Self, String> {
        linux::enter(request).map(|previous| Self { previous })
    }
}

#[cfg(target_os = "linux")]
impl Drop for Guard {
    fn drop(&mut self) {
        linux::leave(&self.previous);
    }
}

#[cfg(not(target_os = "linux"))]
impl Guard {
    /// Real-time scheduling is only implemented for Linux.
    pub fn enter(_request: Realtime) -> Result<Self, String> {
        Err("--realtime is only implemented on Linux".to_string())
    }
}

#[cfg(target_os = "linux")]
mod linux {
    use super::Realtime;
    use std::io;

    /// The thread's scheduling before `enter`.
    #[derive(Debug)]
    pub(super) struct Saved {
        policy: libc::c_int,
        param: libc::sched_param,
        cpus: libc::cpu_set_t,
    }

    fn os_error(what: &str) -> String {
        let e = io::Error::last_os_error();
        let hint = if e.raw_os_error() == Some(libc::EPERM) {
            " (real-time scheduling needs root or CAP_SYS_NICE; run with --realtime off, or \
             e.g. `sudo setcap cap_sys_nice,cap_ipc_lock+ep target/release/hil-sim`)"
        } else {
            ""
        };
        format!("{what}: {e}{hint}")
    }

    pub(super) fn enter(request: Realtime) -> Result<Saved, String> {
        request.check()?;
        // SAFETY: plain calls into the C library on the calling thread (pid 0), with pointers
        // to properly initialised local values that outlive the calls; `cpu_set_t` and
        // `sched_param` are plain data for which all-zero bytes are a valid (empty) value.
        unsafe {
            let mut saved = Saved {
                policy: libc::sched_getscheduler(0),
                param: std::mem::zeroed(),
                cpus: std::mem::zeroed(),
            };
            if saved.policy < 0 || libc::sched_getparam(0, &mut saved.param) != 0 {
                return Err(os_error("reading the scheduling policy"));
            }
            if libc::sched_getaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &mut saved.cpus)
                != 0
            {
                return Err(os_error("reading the CPU affinity"));
            }
            let mut one: libc::cpu_set_t = std::mem::zeroed();
            libc::CPU_SET(request.cpu, &mut one);
            if libc::sched_setaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &one) != 0 {
                return Err(os_error("pinning to the CPU"));
            }
            let param = libc::sched_param {
                sched_priority: request.priority,
            };
            if libc::sched_setscheduler(0, libc::SCHED_FIFO, &param) != 0 {
                let e = os_error("setting SCHED_FIFO");
                libc::sched_setaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &saved.cpus);
                return Err(e);
            }
            if libc::mlockall(libc::MCL_CURRENT | libc::MCL_FUTURE) != 0 {
                let e = os_error("locking memory");
                leave(&saved);
                return Err(e);
            }
            Ok(saved)
        }
    }

    pub(super) fn leave(saved: &Saved) {
        // SAFETY: as in `enter`; failures leave the thread as it is, which is harmless.
        unsafe {
            libc::munlockall();
            libc::sched_setscheduler(0, saved.policy, &saved.param);
            libc::sched_setaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &saved.cpus);
        }
    }
}
