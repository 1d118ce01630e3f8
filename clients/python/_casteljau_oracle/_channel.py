"""One running oracle process: its pipes, the thread that reads its answers, and the
exchange of numbered requests for their answers with a timeout.

Each request line carries an `id` (first in the line, so that the oracle echoes it even
for a line it refuses as too long), and each answer must carry the id of the request it
answers: an answer out of step is never handed back as another request's. A channel that
failed in the middle of an exchange (a timeout, an answer out of step, an exception in the
caller's thread such as KeyboardInterrupt) is ended at once, so that no late answer can be
read by the next exchange; the `Oracle` starts a new one for the next request.
"""

import json
import queue
import subprocess
import threading

from .errors import OracleError, OracleProtocolError, OracleTimeout

_EOF = object()


class Channel:
    """A `casteljau oracle` process and a thread that reads its answer lines into a queue
    (so that a wait for an answer can time out)."""

    def __init__(self, argv):
        try:
            self.proc = subprocess.Popen(argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        except OSError as e:
            raise OracleError(f"cannot run {argv[0]}: {e.strerror or e}") from e
        self._lines = queue.SimpleQueue()
        self._writer = None
        self._reader = threading.Thread(target=self._read_lines, daemon=True)
        self._reader.start()

    def _read_lines(self):
        try:
            while True:
                line = self.proc.stdout.readline()
                if not line:
                    break
                self._lines.put(line)
        except (OSError, ValueError):  # the pipe was closed under the read: the channel ended
            pass
        finally:
            self._lines.put(_EOF)

    def _write_lines(self, data):
        try:
            self.proc.stdin.write(data)
            self.proc.stdin.flush()
        except (OSError, ValueError):  # the oracle stopped: the reader reports it
            pass

    def exchange(self, lines, ids, timeout):
        """Sends `lines` (encoded requests, one per line, with ids `ids`) and returns their
        answers, parsed, in order. Waits at most `timeout` seconds (None: no limit) for each
        answer. A writer thread feeds the oracle while this thread reads, so no batch size
        can fill both pipes and deadlock."""
        self._writer = threading.Thread(target=self._write_lines, args=(b"".join(lines),), daemon=True)
        self._writer.start()
        answers = []
        for expected in ids:
            try:
                line = self._lines.get(timeout=timeout)
            except queue.Empty:
                raise OracleTimeout(
                    f"no answer from the oracle within {timeout} s (request id {expected}); "
                    "the oracle process was ended"
                ) from None
            if line is _EOF:
                try:
                    status = self.proc.wait(timeout=1)
                except subprocess.TimeoutExpired:  # it closed its output but runs on
                    status = None
                raise OracleError(f"the oracle stopped (exit status {status})")
            try:
                answer = json.loads(line)
            except ValueError as e:
                raise OracleProtocolError(f"the oracle's answer is not JSON ({e}): {line[:200]!r}") from None
            got = answer.get("id") if isinstance(answer, dict) else None
            if got != expected or isinstance(got, bool):
                raise OracleProtocolError(
                    f"answer out of step: expected the answer to request id {expected}, got id {got!r}"
                )
            answers.append(answer)
        self._writer.join()
        self._writer = None
        return answers

    def close(self, timeout=30):
        """Ends the oracle by end of input, and kills it if it does not end in `timeout` s."""
        try:
            self.proc.stdin.close()
        except (OSError, ValueError):
            pass
        try:
            self.proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.kill()
            return
        self._close_pipes()

    def kill(self):
        """Ends the oracle at once (also a stopped one), so that nothing it still writes can
        be read as an answer. The process is reaped later (`reap`), so that until then its
        pid still names it."""
        try:
            self.proc.kill()
        except OSError:
            pass
        if self._writer is not None:
            self._writer.join(timeout=10)  # the pipe's reader is gone: the write fails now
        self._close_pipes()

    def reap(self):
        """Collects the exit status of a killed process (no zombie, no ResourceWarning)."""
        try:
            self.proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            pass

    def _close_pipes(self):
        self._reader.join(timeout=10)
        for f in (self.proc.stdin, self.proc.stdout):
            try:
                f.close()
            except (OSError, ValueError):
                pass
