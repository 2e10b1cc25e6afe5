#!/usr/bin/python3
"""Files, special paths, signals and time limits (docs/cli.md, the subsection of that name).

    /usr/bin/python3 tests/cli/test_files_signals.py GMCC_BINARY

Input paths that are not regular files:
  * a FIFO that no program writes: exit 2 within a bounded time (gmcc waits 10 s for a writer),
    one `gmcc: error:` line naming the FIFO; a FIFO whose writer comes late, and a pipe passed
    as /dev/fd/N (what `--image <(...)` gives), are read like the file they carry;
  * /dev/zero and /dev/urandom: exit 2, a NUL-byte message (not "no colours", not a hang);
    /proc/version (size 0 by stat, but text) is read and its first line rejected.
Output paths (`--csv`, `--plot DIR` files):
  * a symbolic link is kept and its target replaced (also a dangling link: its target made);
  * a FIFO is written through to its reader and stays a FIFO; one with no reader: exit 2 in a
    bounded time; /dev/null stays a device; /dev/stdout, /dev/fd/1 and /proc/self/fd/1 put
    the CSV before the table on stdout (also when stdout is a file). /dev/null and /dev/stdout
    are only given once a safe stand-in has passed (a link to /dev/null, /dev/fd/1), so that a
    gmcc that renames onto its output cannot replace them for the whole machine;
  * /proc/version: exit 2, a message naming the path and the proc file system (not "No such
    file or directory"); a directory: exit 2.
Interruptions and limits:
  * SIGTERM, SIGINT, SIGHUP sent a second into a long run: the process dies by that signal, and
    no temporary file (`*.tmp-*`) and no output file is left;
  * --time-limit 1 on a long run (before or after the command's name): exit 3 with
    `gmcc: error: time limit of 1 s reached (--time-limit)`, no temporary or output file;
    --time-limit also ends a wait on a FIFO whose writer never writes;
  * --memory-limit far below what a large input needs: exit 3 with the memory-limit message.
Usage and help:
  * `--help`, `select --help`, `--version` into /dev/full: non-zero exit, the stdout message;
  * an option error: exactly one line, `gmcc: error: ... (run gmcc select --help for usage)`.

The last line is exactly `N passed, N failed`; the exit status is 0 iff none failed.
"""

import json
import os
import signal
import stat
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_harness import Tally  # noqa: E402

TIMEOUT_S = 60
GOOD = b"1,1,1\n2,1,1\n2,2,1\n1,2,1\n"  # chromaticities: the square [1,2]^2
GOOD_IMAGE = b"3,3,2\n"
# A run of several minutes, cut short by the tests (one thread: the shared machine).
LONG_RUN = ["reproduce", "synthetic", "--scenes", "100000", "--threads", "1"]
SMALL_RUN = ["reproduce", "synthetic", "--scenes", "1", "--surfaces", "2", "--threads", "1"]

TALLY = Tally()
check = TALLY.check


def default_signals():
    """A job started in the background by a non-interactive shell inherits SIGINT ignored, and
    gmcc keeps ignored signals ignored (as nohup expects): the tests want the default actions.
    Set here, in this process, not in a preexec_fn (unsafe with threads): a handled signal is
    reset to its default by exec, an ignored one would stay ignored (SIGPIPE is restored by
    subprocess's restore_signals)."""
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    signal.signal(signal.SIGHUP, signal.SIG_DFL)


def run(binary, args, stdout=subprocess.PIPE, timeout=TIMEOUT_S, pass_fds=()):
    start = time.monotonic()
    try:
        p = subprocess.run([binary, *args], stdout=stdout, stderr=subprocess.PIPE,
                           timeout=timeout, pass_fds=pass_fds)
        return p.returncode, p.stdout or b"", p.stderr.decode(errors="replace"), time.monotonic() - start
    except subprocess.TimeoutExpired:
        return None, b"", "(timed out)", time.monotonic() - start


def one_error_line(err):
    lines = [l for l in err.splitlines() if l.strip()]
    return len(lines) == 1 and lines[0].startswith("gmcc: error: ")


def temporaries(root):
    return [os.path.join(d, f) for d, _, files in os.walk(root) for f in files if ".tmp-" in f]


def join_or_unblock(thread, fifo, thread_writes):
    """Join a helper thread that opens `fifo`; if gmcc never opened the other end (a failure
    the checks report), open it here so the thread's open returns and the test goes on."""
    thread.join(timeout=10)
    if thread.is_alive():
        fd = os.open(fifo, (os.O_RDONLY if thread_writes else os.O_WRONLY) | os.O_NONBLOCK)
        thread.join(timeout=10)
        os.close(fd)


def write(path, content):
    with open(path, "wb") as f:
        f.write(content)
    return path


def same_document(out, expected):
    """The same select --json document read through another path: equal but for the paths in
    its provenance, whose inputs must have the same sizes and checksums (docs/cli.md
    "Provenance")."""
    try:
        a, b = json.loads(out), json.loads(expected)
    except ValueError:
        return False
    pa, pb = a.pop("provenance"), b.pop("provenance")
    digests = lambda p: [(f["bytes"], f["sha256"]) for f in p["inputs"]]
    return a == b and digests(pa) == digests(pb)


def test_input_paths(binary, tmp):
    canonical = write(os.path.join(tmp, "canonical.csv"), GOOD)
    image = write(os.path.join(tmp, "image.csv"), GOOD_IMAGE)
    code, expected, err, _ = run(binary, ["select", "--canonical", canonical, "--image", image, "--json"])
    check(code == 0, "select on regular files", err)

    # A FIFO whose writer comes a second late is read like a file.
    late = os.path.join(tmp, "late-writer")
    os.mkfifo(late)

    def late_writer():
        time.sleep(1)
        with open(late, "wb") as f:
            f.write(GOOD_IMAGE)

    t = threading.Thread(target=late_writer)
    t.start()
    code, out, err, _ = run(binary, ["select", "--canonical", canonical, "--image", late, "--json"])
    join_or_unblock(t, late, thread_writes=True)
    check(code == 0 and same_document(out, expected), "FIFO with a late writer reads like the file", err)

    # A pipe as /dev/fd/N, as `--image <(cat image.csv)` passes it.
    r, w = os.pipe()

    def pipe_writer():
        with os.fdopen(w, "wb") as f:
            f.write(GOOD_IMAGE)

    t = threading.Thread(target=pipe_writer)
    t.start()
    code, out, err, _ = run(binary, ["select", "--canonical", canonical, "--image", f"/dev/fd/{r}",
                                     "--json"], pass_fds=(r,))
    t.join()
    os.close(r)
    check(code == 0 and same_document(out, expected),
          "a pipe as /dev/fd/N (process substitution) reads like the file", err)

    # Endless devices: the NUL check runs while reading.
    for dev in ("/dev/zero", "/dev/urandom"):
        if os.path.exists(dev):
            code, out, err, took = run(binary, ["select", "--canonical", canonical, "--image", dev])
            check(code == 2 and out == b"" and one_error_line(err) and f"{dev}:" in err
                  and "NUL byte" in err and took < 30,
                  f"{dev}: exit 2 with the NUL-byte message", f"exit {code}, stderr {err!r}")
    if os.path.exists("/proc/version"):
        code, out, err, _ = run(binary, ["select", "--canonical", "/proc/version", "--image", image])
        check(code == 2 and "/proc/version:1:" in err and "no colours" not in err,
              "/proc/version is read (its size by stat is 0) and its line 1 rejected", err)


def test_output_paths(binary, tmp):
    reference = os.path.join(tmp, "reference.csv")
    code, table, err, _ = run(binary, [*SMALL_RUN, "--csv", reference])
    check(code == 0 and os.path.isfile(reference), "a small run writes its CSV", err)
    csv = open(reference, "rb").read() if os.path.isfile(reference) else b"?"

    # A symbolic link is kept; its target is replaced.
    real_dir = os.path.join(tmp, "real")
    os.mkdir(real_dir)
    target = write(os.path.join(real_dir, "target.csv"), b"old content\n")
    link = os.path.join(tmp, "link.csv")
    os.symlink(os.path.join("real", "target.csv"), link)
    code, _, err, _ = run(binary, [*SMALL_RUN, "--csv", link])
    check(code == 0 and os.path.islink(link) and open(target, "rb").read() == csv,
          "--csv onto a symlink keeps the link and replaces its target", err)
    dangling = os.path.join(tmp, "dangling.csv")
    os.symlink(os.path.join("real", "new.csv"), dangling)
    code, _, err, _ = run(binary, [*SMALL_RUN, "--csv", dangling])
    new = os.path.join(real_dir, "new.csv")
    check(code == 0 and os.path.islink(dangling) and os.path.isfile(new) and open(new, "rb").read() == csv,
          "--csv onto a dangling symlink makes its target", err)
    plot = os.path.join(tmp, "plot")
    os.mkdir(plot)
    dat_target = write(os.path.join(real_dir, "synthetic.dat"), b"old\n")
    os.symlink(dat_target, os.path.join(plot, "synthetic.dat"))
    code, _, err, _ = run(binary, [*SMALL_RUN, "--plot", plot])
    check(code == 0 and os.path.islink(os.path.join(plot, "synthetic.dat"))
          and open(dat_target, "rb").read() != b"old\n",
          "--plot DIR with a symlinked .dat keeps the link and replaces its target", err)

    # A FIFO is written through to its reader, and stays a FIFO.
    fifo = os.path.join(tmp, "out-fifo")
    os.mkfifo(fifo)
    got = []

    def reader():
        with open(fifo, "rb") as f:
            got.append(f.read())

    t = threading.Thread(target=reader)
    t.start()
    code, _, err, _ = run(binary, [*SMALL_RUN, "--csv", fifo])
    join_or_unblock(t, fifo, thread_writes=False)
    check(code == 0 and got == [csv] and stat.S_ISFIFO(os.stat(fifo).st_mode),
          "--csv onto a FIFO writes through to its reader and leaves the FIFO", err)

    # System paths are only given once the same kind of path, made safe, has passed: a gmcc that
    # renamed a temporary file onto its output would replace /dev/null or /dev/stdout (as root)
    # by a regular file for the whole machine. The safe forms: a link in tmp to /dev/null (a
    # rename replaces only the link), and /dev/fd/1 (no file can be made in /proc/self/fd).
    devnull_link = os.path.join(tmp, "devnull-link")
    os.symlink("/dev/null", devnull_link)
    code, _, err, _ = run(binary, [*SMALL_RUN, "--csv", devnull_link])
    devnull_ok = code == 0 and os.path.islink(devnull_link) and stat.S_ISCHR(os.stat("/dev/null").st_mode)
    check(devnull_ok, "--csv LINK to /dev/null: exit 0, the link and the device kept", err)
    if devnull_ok:
        code, _, err, _ = run(binary, [*SMALL_RUN, "--csv", "/dev/null"])
        check(code == 0 and stat.S_ISCHR(os.stat("/dev/null").st_mode), "--csv /dev/null: exit 0, still a device", err)
    code, out, err, _ = run(binary, [*SMALL_RUN, "--csv", "/dev/fd/1"])
    fd1_ok = code == 0 and out == csv + table
    check(fd1_ok, "--csv /dev/fd/1: the CSV, then the table, on stdout", err)
    if fd1_ok:
        code, out, err, _ = run(binary, [*SMALL_RUN, "--csv", "/dev/stdout"])
        check(code == 0 and out == csv + table and os.path.islink("/dev/stdout"),
              "--csv /dev/stdout: the CSV, then the table, on stdout", err)
    with open(os.path.join(tmp, "stdout.txt"), "wb") as f:
        code, _, err, _ = run(binary, [*SMALL_RUN, "--csv", "/proc/self/fd/1"], stdout=f)
    check(code == 0 and open(os.path.join(tmp, "stdout.txt"), "rb").read() == csv + table,
          "--csv /proc/self/fd/1 with stdout a file: the CSV, then the table, in the file", err)

    # Paths that cannot be written: the message says why.
    if os.path.exists("/proc/version"):
        code, out, err, _ = run(binary, [*SMALL_RUN, "--csv", "/proc/version"])
        check(code == 2 and out == b"" and one_error_line(err) and "/proc/version" in err
              and "proc file system" in err and "No such file" not in err,
              "--csv /proc/version: exit 2, names the path and the proc file system", err)
    code, out, err, _ = run(binary, [*SMALL_RUN, "--csv", real_dir])
    check(code == 2 and out == b"" and "is a directory" in err, "--csv DIR: exit 2", err)
    check(temporaries(tmp) == [], f"no temporary files left: {temporaries(tmp)}")


def test_fifos_without_peer(binary, tmp):
    """A FIFO nobody writes (as either input) or reads (as output): a clear message in bounded
    time, not a hang. gmcc waits 10 s for the other end: the three runs go side by side."""
    canonical = write(os.path.join(tmp, "canonical-peer.csv"), GOOD)
    image = write(os.path.join(tmp, "image-peer.csv"), GOOD_IMAGE)
    no_writer, no_reader = os.path.join(tmp, "nobody-writes"), os.path.join(tmp, "nobody-reads")
    os.mkfifo(no_writer)
    os.mkfifo(no_reader)
    cases = [("FIFO with no writer as --canonical", no_writer,
              ["select", "--canonical", no_writer, "--image", image]),
             ("FIFO with no writer as --image", no_writer,
              ["select", "--canonical", canonical, "--image", no_writer]),
             ("--csv onto a FIFO with no reader", no_reader, [*SMALL_RUN, "--csv", no_reader])]
    results = [None] * len(cases)

    def one(i):
        results[i] = run(binary, cases[i][2], timeout=40)

    threads = [threading.Thread(target=one, args=(i,)) for i in range(len(cases))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for (what, fifo, _), (code, out, err, took) in zip(cases, results):
        check(code == 2 and out == b"" and one_error_line(err) and fifo in err and "FIFO" in err
              and took < 30 and stat.S_ISFIFO(os.stat(fifo).st_mode),
              f"{what}: exit 2 in bounded time, one message naming it",
              f"exit {code} after {took:.1f} s, stderr {err!r}")


def test_signals_and_limits(binary, tmp):
    for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        d = os.path.join(tmp, f"signal-{sig.name}")
        os.mkdir(d)
        out_csv = os.path.join(d, "out.csv")
        p = subprocess.Popen([binary, *LONG_RUN, "--csv", out_csv, "--plot", os.path.join(d, "plot")],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        time.sleep(1)
        started = temporaries(d)
        p.send_signal(sig)
        try:
            p.wait(timeout=TIMEOUT_S)
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()
        p.stderr.close()
        check(len(started) == 3, f"{sig.name}: the run had made its 3 temporary files", f"{started}")
        check(p.returncode == -sig, f"{sig.name}: the process dies by the signal (got {p.returncode})")
        check(temporaries(d) == [] and not os.path.exists(out_csv),
              f"{sig.name}: no temporary or output file left", f"{temporaries(d)}")

    for where in ("before", "after"):
        d = os.path.join(tmp, f"time-limit-{where}")
        os.mkdir(d)
        out_csv = os.path.join(d, "out.csv")
        args = [*LONG_RUN, "--csv", out_csv, "--plot", os.path.join(d, "plot")]
        args = ["--time-limit", "1", *args] if where == "before" else [*args, "--time-limit", "1"]
        code, out, err, took = run(binary, args)
        check(code == 3 and out == b"" and one_error_line(err)
              and err.startswith("gmcc: error: time limit of 1 s reached (--time-limit)") and took < 20,
              f"--time-limit 1 {where} the command: exit 3 with the message",
              f"exit {code} after {took:.1f} s, stderr {err!r}")
        check(temporaries(d) == [] and not os.path.exists(out_csv),
              f"--time-limit {where}: no temporary or output file left", f"{temporaries(d)}")

    # A writer that opens the FIFO and never writes: waited for (a legitimate slow producer),
    # but --time-limit ends it.
    fifo = os.path.join(tmp, "silent-writer")
    os.mkfifo(fifo)
    canonical = write(os.path.join(tmp, "canonical-limit.csv"), GOOD)
    release = threading.Event()

    def silent_writer():
        with open(fifo, "wb"):
            release.wait(TIMEOUT_S)

    t = threading.Thread(target=silent_writer)
    t.start()
    code, out, err, took = run(binary, ["--time-limit", "2", "select", "--canonical", canonical, "--image", fifo])
    release.set()
    join_or_unblock(t, fifo, thread_writes=True)
    check(code == 3 and "time limit of 2 s reached" in err and took < 20,
          "--time-limit ends the wait on a FIFO whose writer never writes", f"exit {code}, {err!r}")

    # Memory: 200,000 colours need far more than 100 MiB of address space. Not under
    # AddressSanitizer: its shadow memory alone is terabytes of address space, so RLIMIT_AS
    # makes its own allocator fail (and report) first.
    with open(binary, "rb") as f:
        if b"__asan_init" in f.read():
            print("skipped: --memory-limit under AddressSanitizer")
            return
    big = os.path.join(tmp, "big.csv")
    with open(big, "w") as f:
        for i in range(200000):
            f.write(f"{i + 1}.{i * 7919 % 1000003},{i * 104729 % 999983 + 1},{i % 977 + 1}\n")
    code, out, err, _ = run(binary, ["--memory-limit", "100", "select", "--canonical", big, "--image", big])
    check(code == 3 and out == b"" and one_error_line(err)
          and err.startswith("gmcc: error: memory limit of 100 MiB reached (--memory-limit)"),
          "--memory-limit 100 on a large input: exit 3 with the message", f"exit {code}, {err!r}")


def test_usage(binary):
    if os.path.exists("/dev/full"):
        for args in (["--help"], ["select", "--help"], ["--version"]):
            with open("/dev/full", "wb") as full:
                code, _, err, _ = run(binary, args, stdout=full)
            check(code not in (0, None) and one_error_line(err) and "standard output" in err,
                  f"{' '.join(args)} > /dev/full: non-zero exit with the stdout message", f"exit {code}, {err!r}")
    code, out, err, _ = run(binary, ["select", "--canonical", "a.csv", "--image", "b.csv", "--bogus"])
    check(code == 2 and out == b"" and one_error_line(err) and "--bogus" in err
          and err.rstrip().endswith("(run gmcc select --help for usage)"),
          "an option error is one line with the command's usage hint", repr(err))
    code, out, err, _ = run(binary, [])
    check(code == 2 and one_error_line(err) and err.rstrip().endswith("(run gmcc --help for usage)"),
          "no command: one line with the usage hint", repr(err))
    code, out, err, _ = run(binary, ["--time-limit", "0", "select", "--canonical", "a", "--image", "b"])
    check(code == 2 and one_error_line(err) and "--time-limit" in err, "--time-limit 0 is rejected", repr(err))


def main():
    if len(sys.argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    binary = os.path.abspath(sys.argv[1])
    default_signals()
    with tempfile.TemporaryDirectory(prefix="gmcc-files-signals-") as tmp:
        test_usage(binary)
        test_fifos_without_peer(binary, tmp)
        test_input_paths(binary, tmp)
        test_output_paths(binary, tmp)
        test_signals_and_limits(binary, tmp)
    return TALLY.finish()


if __name__ == "__main__":
    sys.exit(main())
