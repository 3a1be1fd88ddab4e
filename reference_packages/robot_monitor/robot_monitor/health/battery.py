# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""A simulated battery that drains a fixed amount per tick."""

from dataclasses import dataclass


@dataclass(frozen=True)
class BatterySimulation:
    """Battery voltage that starts at ``initial_voltage`` and drops ``drain_per_tick`` per tick."""

    initial_voltage: float = 12.6
    drain_per_tick: float = 0.01
    empty_voltage: float = 0.0

    def voltage_at(self, tick: int) -> float:
        """Return the voltage after ``tick`` drain steps, never below ``empty_voltage``."""
        if tick < 0:
            raise ValueError(f'tick must be >= 0, not {tick}')
        # Rounding keeps 12.6 - 260 * 0.01 at exactly 10.0 instead of 9.999999999999982.
        voltage = round(self.initial_voltage - self.drain_per_tick * tick, 6)
        return max(self.empty_voltage, voltage)


def is_low(voltage: float, threshold: float) -> bool:
    """Return True when ``voltage`` is strictly below the low-battery ``threshold``."""
    return voltage < threshold
