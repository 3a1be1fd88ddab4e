"""NumPy names that no longer exist in the ``numpy`` namespace, and what to write instead.

Checked against NumPy 2.4's ``numpy._expired_attrs_2_0`` and a live ``getattr`` (see
tests/lint/test_dependencies_knowledge.py). ``bool`` and ``long`` came back in NumPy 2.0 with
other meanings, but they are missing from NumPy 1.24-1.26, the versions Ubuntu 24.04 ships
for ROS 2 Jazzy, so code that uses them breaks on the robot.
"""

from __future__ import annotations

from pkgtool.records import record


SYSTEM_NUMPY = {"humble": (1, 21), "jazzy": (1, 26), "kilted": (1, 26), "rolling": (1, 26)}
"""The NumPy release (major, minor) of the Ubuntu release each ROS 2 distribution targets."""


def system_has(removed: "Removed", distro: str) -> bool:
    """True when the NumPy the target's Ubuntu ships still has the name (pip's is newer)."""
    return SYSTEM_NUMPY.get(distro, (1, 26)) < removed.release


@record
class Removed:
    """``removed_in`` is the NumPy release that dropped the name; ``use`` the replacement."""

    removed_in: str
    use: str

    @property
    def release(self) -> tuple[int, int]:
        """The (major, minor) of the NumPy release that dropped the name."""
        major, minor = self.removed_in.split(" ")[0].split(".")[:2]
        return int(major), int(minor)

    @property
    def comes_back(self) -> bool:
        """True for a name NumPy 2.0 has again, with another meaning (``np.bool``)."""
        return "back in" in self.removed_in

    @property
    def lacking(self) -> str:
        """The NumPy releases that lack the name (``2.0 and newer``, ``1.24 to 1.26``)."""
        first = self.removed_in.split(" ")[0]
        return f"{first} to 1.26" if self.comes_back else f"{first} and newer"


_ALIASES_1_24 = {"float": "float", "int": "int", "object": "object", "str": "str",
                 "complex": "complex", "unicode": "str"}
_BACK_IN_2_0 = {"bool": "bool` or `np.bool_", "long": "int` or `np.int_"}

_REMOVED_2_0 = {
    "int0": "np.intp", "uint0": "np.uintp", "bool8": "np.bool_", "float_": "np.float64",
    "complex_": "np.complex128", "cfloat": "np.complex128", "singlecomplex": "np.complex64",
    "longfloat": "np.longdouble", "clongfloat": "np.clongdouble",
    "longcomplex": "np.clongdouble", "string_": "np.bytes_", "unicode_": "np.str_",
    "Inf": "np.inf", "Infinity": "np.inf", "infty": "np.inf", "NaN": "np.nan",
    "NINF": "-np.inf", "PINF": "np.inf", "NZERO": "-0.0", "PZERO": "0.0",
    "product": "np.prod", "cumproduct": "np.cumprod", "alltrue": "np.all",
    "sometrue": "np.any", "round_": "np.round", "asfarray": "np.asarray(a, dtype=float)",
    "msort": "np.sort(a, axis=0)", "mat": "np.asmatrix", "issubclass_": "issubclass",
    "safe_eval": "ast.literal_eval", "find_common_type": "np.result_type",
    "recfromtxt": "np.genfromtxt", "recfromcsv": "np.genfromtxt(..., delimiter=',')",
    "set_string_function": "np.set_printoptions", "cast": "np.asarray(a, dtype=dtype)",
    "source": "inspect.getsource", "byte_bounds": "np.lib.array_utils.byte_bounds",
}
_REMOVED_EARLIER = {"asscalar": ("1.23", "a.item()"), "alen": ("1.23", "len(a)"),
                    "rank": ("1.18", "np.ndim"), "loads": ("1.17", "pickle.loads"),
                    **{name: ("1.20", f"numpy_financial.{name}")  # NEP 32
                       for name in ("fv", "ipmt", "irr", "mirr", "nper", "npv", "pmt", "ppmt",
                                    "pv", "rate")}}
_REMOVED_2_4 = {"trapz": "np.trapezoid", "in1d": "np.isin"}

REMOVED: dict[str, Removed] = {
    **{name: Removed("1.24", f"the builtin `{use}`") for name, use in _ALIASES_1_24.items()},
    **{name: Removed("1.24 (back in 2.0)", f"`{use}`") for name, use in _BACK_IN_2_0.items()},
    **{name: Removed("2.0", f"`{use}`") for name, use in _REMOVED_2_0.items()},
    **{name: Removed(version, f"`{use}`") for name, (version, use) in _REMOVED_EARLIER.items()},
    **{name: Removed("2.4", f"`{use}`") for name, use in _REMOVED_2_4.items()},
}
"""Attribute of ``numpy`` -> when it went away and its replacement."""
