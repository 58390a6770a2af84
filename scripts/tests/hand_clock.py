"""A clock the tests move by hand (for the progress lines' timing)."""


class Clock:
    def __init__(self):
        self.now = 0.0

    def __call__(self):
        return self.now
