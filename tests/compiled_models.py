"""A model's compiled rhs and Jacobian as the simulate path builds them: a
:class:`derive.runtime.kernel.Kernel` over the library :class:`derive.runtime.integrate.ModelKernel`
loads for a method (by default dop853, which the suite builds for its scenes anyway), of the
model :func:`derive.runtime.catalogue.describe` gives (shipped in generated/, else derived once
into the suite's cache). For tests that call a model's C functions."""
import functools

from derive.runtime.catalogue import describe
from derive.runtime.integrate import ModelKernel
from derive.runtime.kernel import Kernel


@functools.lru_cache(maxsize=None)
def compiled_model(formulation: str, symmetric: bool, effects: tuple, method: str = "dop853") -> Kernel:
    desc = describe((formulation, symmetric, effects))
    return Kernel(ModelKernel.load(desc, method).lib, desc.name)
