"""Where the cases of a sweep run: a local process pool or a Dask distributed cluster.

:func:`run_case` (:mod:`.case`) is the worker: it runs one case deck in a private temporary
folder and returns the print text and key results (it never raises and writes nothing the
client reads), so the client writes every file of the sweep folder itself, whichever backend
ran the case.  The local pool starts its worker processes once per sweep, from a fresh
interpreter (``python -m pyadore.sweeps.worker``, jobs and results as JSON lines on its
pipes) that loads the engine extension itself: nothing of the client's state is copied
by a fork (its threads, the Fortran run-time), and unlike multiprocessing's ``spawn`` the
worker never re-imports the client's ``__main__`` (a script without a main guard, stdin).
The ``pyadore sweep`` command forks itself instead, at its entry, before it has any of that
(:func:`start_early`, :func:`_fork_server`).  A worker that dies is known by the one case it
was running.
"""

from __future__ import annotations

import json
import os
import sys
import time
from typing import Callable, Iterable

from .case import run_case  # one case, run where its worker is (:mod:`.case`)

__all__ = ["run_case", "run_local", "run_dask", "WorkerPool", "start_early", "take_early", "WORKER_ENV"]

#: The environment of a local worker process (:mod:`.worker`): one engine (OpenMP) thread and
#: one BLAS thread per worker (a sweep's parallelism is its workers; a forked process must
#: hold one thread).
WORKER_ENV = {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}


def _died(case_id: str, why: str) -> dict:
    return {"case": case_id, "status": "error", "error": why, "notes": [], "print_text": None, "results": {},
            "history_text": None, "results_nc": None,
            "worker": "", "tmp_deck": "", "tmp_print": "", "incomplete_text": None, "incomplete_history": None,
            "duration_s": float("nan")}


def _alive(pid: int) -> bool:
    """Whether process ``pid`` runs (Linux: /proc; a zombie counts as ended)."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as fh:
            state = fh.read().rsplit(b")", 1)[1].split()[0]
    except (OSError, IndexError):
        return False
    return state not in (b"Z", b"X")


def _wait_for(proc, timeout: float | None, what: str):
    """Wait until ``proc`` (a :class:`_Forked` or :class:`_Child`) has ended: blocked on a
    descriptor of its pid (Linux's pidfd, readable once the process has ended) rather than
    polled, so that the sweep's end - its workers', then its fork server's exit - is seen at
    once, not at the next of 1 ms polls (docs/sweeps.md, "Scaling"); polled where there is no
    pidfd.  Its returncode; subprocess.TimeoutExpired after ``timeout`` s."""
    deadline = None if timeout is None else time.monotonic() + timeout
    fd = None
    if proc.pid is not None and hasattr(os, "pidfd_open"):
        try:
            fd = os.pidfd_open(proc.pid)
        except OSError:  # ended and reaped already (poll says so), or no pidfd in this kernel
            fd = None
    try:
        while proc.pid is not None and proc.poll() is None:
            left = None if deadline is None else deadline - time.monotonic()
            if left is not None and left <= 0:
                import subprocess

                raise subprocess.TimeoutExpired(f"{what} {proc.pid}", timeout)
            if fd is not None:
                import select

                select.select([fd], [], [], left)
                if proc.poll() is None:  # readable, yet not seen ended: the state lags; poll on
                    os.close(fd)
                    fd = None
            else:
                time.sleep(0.001)
    finally:
        if fd is not None:
            os.close(fd)
    return proc.returncode


class _Forked:
    """A worker forked by the first worker of its group (:mod:`.worker`): not a child of this
    process, so known by its pid (from its ready line) and polled through /proc."""

    def __init__(self) -> None:
        self.pid: int | None = None
        self.returncode: int | None = None

    def poll(self):
        if self.returncode is None and self.pid is not None and not _alive(self.pid):
            self.returncode = -1  # its status went to its parent
        return self.returncode

    def kill(self) -> None:
        import signal

        if self.pid is not None and self.poll() is None:
            try:
                os.kill(self.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass

    def wait(self, timeout: float | None = None):
        return _wait_for(self, timeout, "worker")


class _Child:
    """The fork server forked by this process (:func:`_fork_server`): a child known by its pid,
    waited for with waitpid (the Popen methods the pool uses: poll, wait, kill)."""

    def __init__(self, pid: int) -> None:
        self.pid = pid
        self.returncode: int | None = None

    def poll(self):
        if self.returncode is None:
            try:
                pid, status = os.waitpid(self.pid, os.WNOHANG)
            except ChildProcessError:
                self.returncode = -1
            else:
                if pid:
                    self.returncode = os.waitstatus_to_exitcode(status)
        return self.returncode

    def wait(self, timeout: float | None = None):
        return _wait_for(self, timeout, "fork server")

    def kill(self) -> None:
        import signal

        if self.poll() is None:
            try:
                os.kill(self.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass


def _fork_server(slots: list[tuple[int, int]]) -> _Child:
    """Fork this process into the fork server of ``slots`` (Linux; :func:`start_early` only:
    the ``pyadore`` command at its very start, a single thread that has imported nothing but
    its signal handlers and this module - no engine, no Fortran run-time, no numpy).  The
    child is what ``python -m pyadore.sweeps.worker --slots ...`` is, without a second
    interpreter start: the interpreter, ``site`` with the editable install's loader and its
    rebuild check (about 0.1 s of CPU of the sweep's serial start, docs/sweeps.md "Scaling").
    It keeps only its slots' descriptors and the standard streams (stdin from /dev/null),
    ignores SIGINT and takes SIGTERM and SIGHUP by default, as the worker process does."""
    import signal

    pid = os.fork()
    if pid:
        return _Child(pid)
    code = 1
    try:
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        for name in ("SIGTERM", "SIGHUP"):
            signal.signal(getattr(signal, name), signal.SIG_DFL)
        keep = {0, 1, 2} | {fd for pair in slots for fd in pair}
        for name in os.listdir("/proc/self/fd"):  # the client's ends of every channel above all
            if int(name) not in keep:
                try:
                    os.close(int(name))
                except OSError:
                    pass
        null = os.open(os.devnull, os.O_RDONLY)
        os.dup2(null, 0)
        os.close(null)
        os.environ.update(WORKER_ENV)  # before the engine (OpenMP) loads
        from . import worker

        code = worker.main(["--slots", ",".join(f"{r}:{w}" for r, w in slots)])
    except BaseException:
        try:
            import traceback

            traceback.print_exc()
        except BaseException:
            pass
    finally:
        os._exit(code)


def _start_group(workers: list["_Worker"], fork: bool = False) -> None:
    """Start worker processes for ``workers``: on Linux one fresh interpreter that, once warm,
    forks one process per further worker (one start-up for the group, :mod:`.worker`) - or,
    ``fork`` (:func:`start_early`: the command's first moments), this process forked into
    that fork server (:func:`_fork_server`); on other POSIX systems one process each, on
    pipes passed by descriptor; elsewhere one process each on its stdin and stdout.  Each
    process runs one engine thread (:data:`WORKER_ENV`)."""
    import subprocess

    env = {**os.environ, **WORKER_ENV}
    cmd = [sys.executable, "-m", "pyadore.sweeps.worker"]
    if os.name != "posix":
        for w in workers:
            proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, encoding="utf-8",
                                    env=env)
            w._attach(proc, proc.stdin, proc.stdout)
        return
    groups = [workers] if sys.platform.startswith("linux") else [[w] for w in workers]
    # (Linux: one fork server for the group, :mod:`.worker`; it ends when its workers have)
    for group in groups:
        theirs, mine, slots = [], [], []
        try:
            for _ in group:
                job_r, job_w = os.pipe()
                res_r, res_w = os.pipe()
                theirs += [job_r, res_w]
                mine.append((job_w, res_r))
                slots.append(f"{job_r}:{res_w}")
            if fork and sys.platform.startswith("linux"):
                proc = _fork_server([tuple(int(x) for x in s.split(":")) for s in slots])
            else:
                proc = subprocess.Popen(cmd + ["--slots", ",".join(slots)], stdin=subprocess.DEVNULL, env=env,
                                        pass_fds=theirs)
        except BaseException:
            for fd in theirs + [fd for pair in mine for fd in pair]:
                os.close(fd)
            raise
        for fd in theirs:  # only the worker holds its ends: its death closes the channel
            os.close(fd)
        forked = sys.platform.startswith("linux")
        for w, (job_w, res_r) in zip(group, mine):
            w._attach(_Forked() if forked else proc, os.fdopen(job_w, "w", encoding="utf-8"),
                      os.fdopen(res_r, "r", encoding="utf-8"), server=proc if forked else None)


class _Worker:
    """One local worker process (:mod:`pyadore.sweeps.worker`), started on demand and
    restarted after a crash; :meth:`serve` feeds it one sweep's jobs in a thread."""

    def __init__(self) -> None:
        import threading

        self.proc = None        # a Popen, or a _Forked for a worker its group's first one forked
        self.jobs = None        # its job channel (text, written here)
        self.results = None     # its result channel (text, read here)
        self.ready = False      # its ready line was read: it is warm and its pid known
        self.server = None      # the fork server that forked it (Linux)
        self.boot: dict = {}    # its ready line: pid, the boot's CPU time and end (the bench's budget)
        self.interrupted = threading.Event()  # set by kill(): serve() ends without a report

    def _attach(self, proc, jobs, results, server=None) -> None:
        self.proc, self.jobs, self.results, self.ready = proc, jobs, results, False
        self.server = server  # the fork server of a forked worker (a Popen): reaped by the pool

    def running(self) -> bool:
        """Whether a process serves (or boots for) this worker."""
        return self.proc is not None and self.proc.poll() is None

    def start(self) -> None:
        """Start the process unless it runs (it boots while the client prepares cases)."""
        if not self.running():
            self.stop()
            _start_group([self])

    def _await_ready(self) -> None:
        line = self.results.readline()
        if not line:
            raise OSError("the worker ended before it was ready")
        self.boot = json.loads(line)  # {"ready": pid, "boot_cpu_s": ..., "booted_at": ...}
        pid = self.boot["ready"]
        if isinstance(self.proc, _Forked):
            self.proc.pid = pid
        self.ready = True

    def serve(self, jobs, results, once: bool = False) -> None:
        """Run jobs from the queue ``jobs`` until a None; each result, then a None, to ``results``.
        A result's next job is written to the worker before the result is decoded and handed
        over (the worker idles only while its result and the next job cross the pipes, not
        while this thread decodes the result and the client's thread takes it; docs/sweeps.md,
        "Scaling").  After :meth:`kill` (the sweep was interrupted) it ends quietly: the
        process it was waiting on is gone on purpose, not a crash to report, and none is
        started again.  ``once`` (a pool of one sweep): at the None the worker is told to end
        (its job channel closed), so it exits while the client records the last results."""
        job = jobs.get()
        sent = False  # whether ``job`` went to the worker already, ahead of the previous result
        while True:
            if job is None and once and self.ready:
                try:
                    self.jobs.close()
                except (OSError, ValueError, AttributeError):
                    pass
            if job is None or self.interrupted.is_set():
                break
            proc = self.proc if sent else None
            try:
                if not sent:
                    self.start()
                    proc = self.proc  # kill() may set self.proc to None from the client's thread
                    if not self.ready:
                        self._await_ready()
                    self.jobs.write(json.dumps(list(job)) + "\n")
                    self.jobs.flush()
                line = self.results.readline()
            except (OSError, ValueError, AttributeError, KeyError, TypeError):
                line = ""
            sent = False
            if self.interrupted.is_set():
                break
            if not line:  # the process died on this job: report it, go on with a fresh one
                code = proc.poll() if proc is not None else None
                results.put(_died(job[0], f"the worker process died while running this case (exit status "
                                          f"{'unknown' if code is None or code == -1 else code}): a crash of "
                                          f"the engine"))
                self.stop()
                job = jobs.get()
                continue
            job = jobs.get()  # the next job, to the worker at once (a failed write: sent with a fresh one)
            if job is not None and not self.interrupted.is_set():
                try:
                    self.jobs.write(json.dumps(list(job)) + "\n")
                    self.jobs.flush()
                    sent = True
                except (OSError, ValueError, AttributeError):
                    sent = False
            results.put(json.loads(line))
        results.put(None)

    def _close_channels(self) -> None:
        for ch in (self.jobs, self.results):
            try:
                if ch is not None:
                    ch.close()
            except (OSError, ValueError):
                pass
        self.jobs = self.results = None

    def stop(self) -> None:
        """Close the job channel (a warm worker exits when idle) and end the process if it
        does not; a worker still booting (it never served) is ended at once."""
        proc = self.proc
        if proc is not None and self.ready:
            try:
                self.jobs.close()  # (closing a closed file does nothing)
            except (OSError, ValueError, AttributeError):
                pass
            try:
                proc.wait(timeout=5)
            except Exception:
                proc.kill()
        elif proc is not None:
            proc.kill()
            try:
                proc.wait(timeout=5)
            except Exception:
                pass
        self._close_channels()
        self.proc = None
        self.ready = False

    def kill(self) -> None:
        """End the worker now (the sweep was interrupted)."""
        self.interrupted.set()
        proc, self.proc = self.proc, None
        self.ready = False
        if proc is None:
            return
        proc.kill()
        try:
            proc.wait(timeout=5)
        except Exception:
            pass
        try:  # a forked worker whose pid is not known yet ends at the end of its job channel
            if self.jobs is not None:
                self.jobs.close()
        except (OSError, ValueError):
            pass


class WorkerPool:
    """Local worker processes that stay warm across sweeps: ``with WorkerPool(2) as pool:``
    then ``pyadore.sweep(..., workers=pool)`` as often as needed.  The processes boot once
    (on Linux one interpreter start for the whole pool, which forks the others once warm:
    the interpreter, numpy, the engine, about 0.4 s of CPU, docs/sweeps.md "Scaling"), at
    :meth:`start` or the first sweep, instead of at every sweep; :meth:`close` (or the end of
    the ``with``) ends them, and they end by themselves when this process exits."""

    def __init__(self, workers: int) -> None:
        if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
            raise ValueError(f"workers must be an integer >= 1, got {workers!r}")
        self.size = workers
        self._workers = [_Worker() for _ in range(workers)]
        #: the pool serves one sweep (a sweep's own, the command's): its workers end with its last job
        self.once = False

    def __enter__(self) -> "WorkerPool":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def __repr__(self) -> str:
        running = sum(w.proc is not None for w in self._workers)
        return f"WorkerPool({self.size}, {running} running)"

    def start(self, count: int | None = None) -> "WorkerPool":
        """Start the first ``count`` workers (all by default) that do not run, as one group:
        they boot while the caller goes on (a sweep starts its pool before it reads the deck)."""
        return self._start(count)

    def _start(self, count: int | None = None, fork: bool = False) -> "WorkerPool":
        idle = [w for w in self._workers[:self.size if count is None else count] if not w.running()]
        for w in idle:
            w.stop()
        if idle:
            _start_group(idle, fork=fork)
        return self

    def close(self) -> None:
        """End the worker processes (a later sweep on this pool starts them again), then
        their fork servers (which end with their workers)."""
        servers: dict[int, list] = {}  # id -> [the fork server, whether one of its workers served]
        for w in self._workers:
            if w.server is not None:
                servers.setdefault(id(w.server), [w.server, False])[1] |= w.ready
        for w in self._workers:  # every warm worker told first, so that they end together
            if w.ready and w.jobs is not None:
                try:
                    w.jobs.close()
                except (OSError, ValueError):
                    pass
        for w in self._workers:
            w.stop()
            w.server = None
        for server, served in servers.values():
            if not served:  # still booting (a sweep with nothing to run): no need to wait for it
                server.kill()
            try:
                server.wait(timeout=5)
            except Exception:
                server.kill()
                server.wait()


#: The pool :func:`start_early` started for this process's ``pyadore sweep`` command (at most one).
_EARLY: list[WorkerPool] = []


def start_early(argv: list[str]) -> None:
    """Start the workers of a local ``pyadore sweep`` command line (``argv``: the command's
    arguments) before the command's own modules load: click, the option table and with it
    numpy and the engine extension cost the client about 0.2 s of CPU before the sweep
    command runs, time the workers' boot can overlap (docs/sweeps.md, "Scaling").  Nothing
    for another command, ``--help``, ``--scheduler`` or a ``--workers`` that is no number
    >= 1; the sweep command takes the pool (:func:`take_early`) or, when its workers differ,
    closes it."""
    if not argv or argv[0] != "sweep" or any(a in ("--help", "-h") or a.startswith("--scheduler") for a in argv):
        return
    workers = os.cpu_count() or 1
    for i, arg in enumerate(argv[1:], start=1):
        if arg == "--workers" and i + 1 < len(argv):
            value = argv[i + 1]
        elif arg.startswith("--workers="):
            value = arg.split("=", 1)[1]
        else:
            continue
        try:
            workers = int(value)
        except ValueError:
            return
    if workers >= 1:
        # forked from this process: it has imported nothing yet that a fork must not copy
        pool = WorkerPool(workers)
        pool.once = True  # the command's one sweep
        _EARLY.append(pool._start(fork=True))


def take_early(workers: int) -> WorkerPool | None:
    """The pool :func:`start_early` started, when it has ``workers`` workers (one that has
    not is closed); None when there is none."""
    pool = _EARLY.pop() if _EARLY else None
    if pool is not None and pool.size != workers:
        pool.close()
        pool = None
    return pool


class _Pending:
    """The jobs no worker has taken yet (the interface of ``queue.Queue`` that :meth:`_Worker.serve`
    and :func:`run_local` use: put, get, get_nowait): first in, first out, or with ``rank`` the
    job of the highest ``rank(job)`` first, ranked when a worker takes one (so that a rank
    learnt from the cases finished meanwhile orders the rest; :func:`run_local`).  A None (a
    worker's end) is taken only when no job is left."""

    def __init__(self, rank: Callable[[tuple], object] | None = None) -> None:
        import threading

        self._ready = threading.Condition()
        self._jobs: list = []
        self._ends = 0
        self._rank = rank

    def put(self, job) -> None:
        with self._ready:
            if job is None:
                self._ends += 1
            else:
                self._jobs.append(job)
            self._ready.notify()

    def _take(self):
        if self._jobs:
            k = 0
            if self._rank is not None and len(self._jobs) > 1:
                rank = self._rank
                try:
                    k = max(range(len(self._jobs)), key=lambda i: rank(self._jobs[i]))
                except Exception:  # a rank that fails orders nothing: first in, first out
                    k = 0
            return self._jobs.pop(k)
        self._ends -= 1
        return None

    def get(self):
        with self._ready:
            while not self._jobs and not self._ends:
                self._ready.wait()
            return self._take()

    def get_nowait(self):
        import queue

        with self._ready:
            if not self._jobs and not self._ends:
                raise queue.Empty
            return self._take()


def run_local(jobs: Iterable[tuple], workers, on_result: Callable[[dict], None], count: int,
              rank: Callable[[tuple], object] | None = None) -> None:
    """Run ``jobs`` (tuples of :func:`run_case` arguments, at most ``count``) on ``workers``
    local worker processes (a number: started for this sweep when the first job comes, so
    they boot while the client prepares the next ones, and ended after it; or a
    :class:`WorkerPool`, whose processes stay warm, possibly started already by
    :meth:`WorkerPool.start`); ``on_result`` gets each
    :func:`run_case` result, in this thread, as it arrives.  A case whose process dies (a
    crash in the engine) is reported as an error and a fresh process takes the next case;
    the others are not affected.  ``rank`` (a job's key; None: the jobs' own order): a worker
    free for a job takes the job of the highest rank among those not taken yet, ranked then,
    so that a rank that learns from the results ``on_result`` gets orders the rest."""
    import queue
    import threading

    own = not isinstance(workers, WorkerPool)
    pool = WorkerPool(max(1, min(workers, count))) if own else workers
    pool.once = pool.once or own
    pending = _Pending(rank)
    results: queue.Queue = queue.Queue()
    used: list[_Worker] = []
    try:
        for job in jobs:
            if not used:
                used = pool._workers[:max(1, min(pool.size, count))]
                pool.start(len(used))  # those not started yet (sweep() starts its pool early)
                for w in used:
                    w.interrupted.clear()  # a pool's worker serves again after an interrupted sweep
                    threading.Thread(target=w.serve, args=(pending, results, pool.once), daemon=True).start()
            pending.put(job)
        for _ in used:
            pending.put(None)  # no more jobs: each worker's thread ends after its last one
        running = len(used)
        while running:
            try:
                res = results.get(timeout=0.5)
            except queue.Empty:
                continue
            if res is None:
                running -= 1
                continue
            on_result(res)
    except BaseException:
        while True:  # nothing more is started
            try:
                pending.get_nowait()
            except queue.Empty:
                break
        for w in used:
            pending.put(None)
            w.kill()
        raise
    finally:
        if own:
            pool.close()


def run_dask(jobs: Iterable[tuple], scheduler, on_result: Callable[[dict], None]) -> None:
    """Run ``jobs`` on a Dask distributed cluster: ``scheduler`` is its address
    (``tcp://host:8786``) or a ``distributed.Client``.  The workers need pyadore installed."""
    from .grid import SweepError

    try:
        from distributed import Client, as_completed
    except ImportError:
        raise SweepError("--scheduler needs dask.distributed: pip install 'pyadore[dask]'") from None
    own = not isinstance(scheduler, Client)
    if own:
        try:
            client = Client(scheduler, timeout="20s", set_as_default=False)
        except (OSError, TimeoutError, ValueError) as exc:
            raise SweepError(f"--scheduler {scheduler}: cannot reach the Dask scheduler ({exc})") from None
    else:
        client = scheduler
    futures = {}
    try:
        token = os.urandom(4).hex()
        for job in jobs:  # submitted as the client prepares them
            futures[client.submit(run_case, *job, key=f"pyadore-sweep-{job[0]}-{token}", pure=False)] = job
        if not futures:
            return
        for fut in as_completed(list(futures), loop=client.loop):
            job = futures[fut]
            try:
                res = fut.result()
            except Exception as exc:  # e.g. KilledWorker: the case's worker died
                res = _died(job[0], f"the Dask worker failed on this case ({type(exc).__name__}: {exc})")
            on_result(res)
    except BaseException:
        if futures:
            client.cancel(list(futures))
        raise
    finally:
        if own:
            client.close()
