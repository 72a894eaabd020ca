"""An interrupt request timed on the CPU clock of the thread it interrupts.

A test that stops a long compiled loop from another thread must be sure the loop has started
and run a while. A wall-clock timer is not: on a loaded machine the calling thread may not have
reached the loop when the timer fires. The calling thread's own CPU clock only advances while it
runs, so ``seconds`` of it mean the loop has had that much time on a core."""
import threading
import time


class CpuTimer(threading.Thread):
    """Call ``action`` once the thread that created this timer has used ``seconds`` of CPU
    since :meth:`start` (checked every 10 ms of wall time). :meth:`cancel` stops it unfired."""

    def __init__(self, seconds: float, action):
        super().__init__(daemon=True)
        self.seconds, self.action = seconds, action
        self.clock = time.pthread_getcpuclockid(threading.get_ident())
        self.stopped = threading.Event()

    def start(self):
        self.begin = time.clock_gettime(self.clock)
        super().start()

    def run(self):
        while not self.stopped.wait(0.01):
            if time.clock_gettime(self.clock) - self.begin >= self.seconds:
                self.action()
                return

    def cancel(self):
        self.stopped.set()
