"""Mapping between a joint position and the integer steps of a Qt slider."""

SLIDER_STEPS = 10000


def to_step(position, lower, upper, steps=SLIDER_STEPS):
    """Nearest slider step (0..steps, an int as Qt requires) for a position."""
    if upper <= lower:
        return 0
    fraction = (position - lower) / (upper - lower)
    return int(round(min(max(fraction, 0.0), 1.0) * steps))


def from_step(step, lower, upper, steps=SLIDER_STEPS):
    """Position at a slider step; the middle step is exactly the middle of the range."""
    if upper <= lower:
        return lower
    if 2 * step == steps:
        return (lower + upper) / 2.0
    return lower + (upper - lower) * step / steps
