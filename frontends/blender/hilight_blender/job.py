"""One hilight run in the background: started, polled, cancelled. No bpy.

hilight prints its stages ("hilight: solving...") only to a terminal, so on
POSIX its stderr is a pseudo-terminal and the stages reach Blender's status
bar; elsewhere a pipe (errors and the summary still arrive).
"""
import os
import subprocess
import threading
import time

try:
    import pty
except ImportError:  # Windows
    pty = None


class Job:
    def __init__(self, argv, cwd=None):
        self.argv = list(argv)
        self.cwd = cwd
        self.proc = None
        self.text = ""
        self.started = None
        self._fd = None
        self._thread = None
        self._lock = threading.Lock()

    def start(self):
        """Starts hilight; raises OSError (e.g. no such executable)."""
        self.started = time.monotonic()
        if pty is not None:
            master, slave = pty.openpty()
            try:
                self.proc = subprocess.Popen(self.argv, cwd=self.cwd, stdin=subprocess.DEVNULL,
                                             stdout=subprocess.DEVNULL, stderr=slave, close_fds=True)
            except BaseException:
                os.close(master)
                raise
            finally:
                os.close(slave)
            os.set_blocking(master, False)
            self._fd = master
        else:
            self.proc = subprocess.Popen(self.argv, cwd=self.cwd, stdin=subprocess.DEVNULL,
                                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            self._thread = threading.Thread(target=self._pump, daemon=True)
            self._thread.start()

    def _pump(self):
        for chunk in iter(lambda: self.proc.stderr.read1(4096), b""):
            with self._lock:
                self.text += chunk.decode("utf-8", "replace")

    def _drain(self):
        if self._fd is None:
            return
        while True:
            try:
                chunk = os.read(self._fd, 65536)
            except BlockingIOError:
                return
            except OSError:  # EIO: the child closed its side
                chunk = b""
            if not chunk:
                os.close(self._fd)
                self._fd = None
                return
            self.text += chunk.decode("utf-8", "replace")

    def poll(self):
        """None while running, else the exit code (output fully read)."""
        self._drain()
        code = self.proc.poll()
        if code is None:
            return None
        if self._thread is not None:
            self._thread.join(5.0)
        while self._fd is not None:
            self._drain()
            if self._fd is not None:
                time.sleep(0.01)
        return code

    def lines(self):
        with self._lock:
            text = self.text
        return [l.strip() for l in text.replace("\r", "\n").split("\n") if l.strip()]

    def last_line(self):
        lines = self.lines()
        return lines[-1] if lines else ""

    def seconds(self):
        return 0.0 if self.started is None else time.monotonic() - self.started

    def cancel(self):
        """Stops hilight (SIGTERM, then SIGKILL after 3 s) and reaps it."""
        if self.proc is None or self.proc.poll() is not None:
            return
        self.proc.terminate()
        try:
            self.proc.wait(3.0)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        self._drain()
        if self._fd is not None:
            os.close(self._fd)
            self._fd = None
