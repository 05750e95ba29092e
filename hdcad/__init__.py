"""hdcad: design-guide generator for strain wave gears (Harmonic Drive®)."""

__version__ = "0.1.0"
