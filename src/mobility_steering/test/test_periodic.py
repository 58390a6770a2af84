import threading
import unittest

from mobility_steering.periodic import PeriodicThread, next_deadline


class NextDeadlineTest(unittest.TestCase):
    def test_on_time_wakeup_keeps_the_grid(self):
        self.assertAlmostEqual(next_deadline(10.0, 10.01, 0.1), 10.1)

    def test_late_wakeup_skips_missed_ticks(self):
        self.assertAlmostEqual(next_deadline(10.0, 10.35, 0.1), 10.4)

    def test_rejects_non_positive_period(self):
        with self.assertRaisesRegex(ValueError, 'got 0'):
            next_deadline(0.0, 0.0, 0)


class PeriodicThreadTest(unittest.TestCase):
    def test_calls_back_until_stopped(self):
        calls = []
        enough = threading.Event()

        def callback():
            calls.append(1)
            if len(calls) == 5:
                enough.set()

        ticker = PeriodicThread(0.01, callback)
        ticker.start()
        self.assertTrue(enough.wait(5.0))
        ticker.stop()
        count = len(calls)
        self.assertGreaterEqual(count, 5)
        self.assertFalse(ticker._thread.is_alive())
