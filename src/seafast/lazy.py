"""Lazy package exports: a package's public names are imported on first use.

Importing a package such as :mod:`seafast.studies` (the command line does, to build its parser)
then costs nothing beyond the package's ``__init__``: numpy, scipy, xarray, pydantic and
matplotlib load only when a name that needs them is first used.

Usage in a package's ``__init__.py``::

    from typing import TYPE_CHECKING

    from seafast.lazy import lazy_exports

    if TYPE_CHECKING:  # what type checkers and readers see: the same names, imported eagerly
        from seafast.studies.limits import DesignLimits

    EXPORTS = {"seafast.studies.limits": ("DesignLimits",)}
    __all__ = ["DesignLimits"]
    lazy_exports(__name__, EXPORTS)

The three lists (the static imports, ``EXPORTS`` and ``__all__``) name the same objects;
``tests/cli/test_startup.py`` checks that they agree.

A submodule not listed (``seafast.studies.limits`` itself) is imported on attribute access too,
as it was when the package imported it eagerly. Mechanism: the package module's class becomes
:class:`LazyPackage` (a :class:`types.ModuleType` with ``__getattr__``; see "Customizing module
attribute access" in the Python reference).
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
import types
from collections.abc import Mapping, Sequence
from typing import Any

__all__ = ["LazyPackage", "lazy_exports"]


class LazyPackage(types.ModuleType):
    """A package module whose exports are imported on first attribute access.

    ``__lazy_exports__`` maps each exported name to its defining module. Python binds an
    imported submodule ``package.name`` as the package's attribute ``name``; where the package
    exports an object of that name (:func:`seafast.output.report.study_figures` in the module of
    the same name), the object is bound instead, as when the package imported it eagerly.
    """

    __lazy_exports__: dict[str, str]

    def __getattr__(self, name: str) -> Any:
        module = self.__lazy_exports__.get(name)
        if module is not None:
            value = getattr(importlib.import_module(module), name)
        elif not name.startswith("__") and importlib.util.find_spec(f"{self.__name__}.{name}") is not None:
            value = importlib.import_module(f"{self.__name__}.{name}")
        else:
            raise AttributeError(f"module {self.__name__!r} has no attribute {name!r}")
        setattr(self, name, value)
        return getattr(self, name)

    def __setattr__(self, name: str, value: Any) -> None:
        defining = self.__dict__.get("__lazy_exports__", {}).get(name)
        if defining is not None and isinstance(value, types.ModuleType) and value.__name__ == f"{self.__name__}.{name}":
            value = getattr(importlib.import_module(defining), name)
        super().__setattr__(name, value)

    def __dir__(self) -> list[str]:
        return sorted(set(self.__dict__) | set(self.__lazy_exports__))


def lazy_exports(package: str, exports: Mapping[str, Sequence[str]]) -> None:
    """Make the (partly initialised) package ``package`` import its exports on first use.

    Parameters
    ----------
    package : str
        The package's ``__name__``; called at the end of its ``__init__.py``.
    exports : mapping of str to sequence of str
        Defining module (absolute name) to the public names taken from it.
    """
    module = sys.modules[package]
    module.__dict__["__lazy_exports__"] = {name: defining for defining, names in exports.items() for name in names}
    module.__class__ = LazyPackage
