# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""A simulated motor temperature and its warning levels."""

from dataclasses import dataclass
from enum import Enum
import math


class TemperatureLevel(Enum):
    """How worrying a temperature is."""

    OK = 'ok'
    WARNING = 'warning'
    CRITICAL = 'critical'


@dataclass(frozen=True)
class TemperatureSimulation:
    """A motor warming from ``ambient`` towards ``steady_state`` (first-order response)."""

    ambient_celsius: float = 25.0
    steady_state_celsius: float = 80.0
    time_constant_ticks: float = 60.0

    def temperature_at(self, tick: int) -> float:
        """Return the temperature in degrees Celsius after ``tick`` ticks."""
        if tick < 0:
            raise ValueError(f'tick must be >= 0, not {tick}')
        if self.time_constant_ticks <= 0.0:
            raise ValueError('time_constant_ticks must be > 0')
        rise = self.steady_state_celsius - self.ambient_celsius
        return self.ambient_celsius + rise * (1.0 - math.exp(-tick / self.time_constant_ticks))


def classify(celsius: float, warning: float, critical: float) -> TemperatureLevel:
    """Return the level of ``celsius`` given the warning and critical thresholds."""
    if warning > critical:
        raise ValueError(f'warning threshold {warning} is above critical threshold {critical}')
    if celsius >= critical:
        return TemperatureLevel.CRITICAL
    if celsius >= warning:
        return TemperatureLevel.WARNING
    return TemperatureLevel.OK
