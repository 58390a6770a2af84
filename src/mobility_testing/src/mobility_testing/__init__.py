"""Support for tests that drive real windows under an X server (Xvfb)."""
