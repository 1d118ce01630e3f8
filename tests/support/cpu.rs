//! CPU time, for tests that bound the work of what they run, and for the benches and the
//! timing tools (`scripts/exact_grid.rs`, `scripts/gcd_peers.rs`): on a loaded machine wall
//! time counts the other processes too, CPU time only what was run.

// Each binary that includes this module uses some of its functions.
#![allow(dead_code)]

use std::io::Read;
use std::process::{Command, Output, Stdio};
use std::time::Duration;

/// The CPU time (user + system) of the calling thread, to the nanosecond (the thread's CPU
/// clock, `clock_gettime(CLOCK_THREAD_CPUTIME_ID)`).
pub fn thread_cpu() -> Duration {
    let t = rustix::time::clock_gettime(rustix::time::ClockId::ThreadCPUTime);
    Duration::new(t.tv_sec.unsigned_abs(), t.tv_nsec as u32)
}

/// The user + system time of process `pid` from `/proc/<pid>/stat`, and whether it has ended
/// (a zombie, not yet waited for: its times are final).
fn process_cpu(pid: u32) -> (Duration, bool) {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).expect("Linux /proc");
    // The fields after the command name (which may hold spaces) start after the last ')'.
    let rest = &stat[stat.rfind(')').expect("a command name") + 2..];
    let fields: Vec<&str> = rest.split_whitespace().collect();
    // utime and stime are fields 14 and 15 of the line, 12 and 13 here, in clock ticks (100 Hz
    // on Linux); the state is field 3, 1 here.
    let ticks: u64 = fields[11].parse::<u64>().unwrap() + fields[12].parse::<u64>().unwrap();
    (Duration::from_millis(ticks * 10), fields[0] == "Z")
}

/// Runs `cmd` to its end with its output captured, and the CPU time (user + system, to 10 ms)
/// the process took: read while it is a zombie, before it is waited for.
pub fn run_timed(cmd: &mut Command) -> (Output, Duration) {
    let mut child = cmd
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the command starts");
    let mut err_pipe = child.stderr.take().expect("piped");
    let stderr = std::thread::spawn(move || {
        let mut buf = Vec::new();
        err_pipe.read_to_end(&mut buf).expect("stderr");
        buf
    });
    let mut stdout = Vec::new();
    child
        .stdout
        .take()
        .expect("piped")
        .read_to_end(&mut stdout)
        .expect("stdout");
    let cpu = loop {
        match process_cpu(child.id()) {
            (cpu, true) => break cpu,
            _ => std::thread::sleep(Duration::from_millis(1)),
        }
    };
    let status = child.wait().expect("the command ends");
    let stderr = stderr.join().expect("the stderr reader");
    (Output { status, stdout, stderr }, cpu)
}
