"""The instantaneous centre of rotation (iCOR) of a pushed nanorod: thesis chapters 4-5.

Geometry (thesis Fig 4.1): a rod of length L = 2b pushed perpendicular to its axis at yn
>= 0 from the centre of mass (CM). R > 0 is the distance from the CM to the iCOR on the
far side from the push (chapter 4). All values SI: m, N, kg, J; k2 = I/m [m^2].

Formulas (NumPy arrays of any shape, broadcast; scalars give floats):
  experimental_fit(yn, L)   eq 4.1       falvo(yn, L)            eq 4.2
  li(yn, L)                 eq 4.3       unknown_pressure(yn, L) eq 4.13
  minimum_force(mu, W, yn, L)            eq 4.8 [N]
  known_pressure(mu, W, yn, F, L)        eq 4.7
  force_from_icor(mu, W, R, L)           eq 4.10 [N]
  force_unknown_pressure(mu, W, R, yn, L)  eq 4.11 [N]
  constrained_force(mu, W, R, yn, L, k2) eq 5.2 [N]
  impulsive(yn, k2)                      eq 5.5
The constrained cubic (5.4): cubic_roots(yn, L, k2, solver) by 'brent', 'eigen' (C++),
'brent_f77', 'lapack_f77' (FORTRAN 77); cubic_branches over arrays.
Beyond the thesis: from_velocity, line_contact_wrench, rectangle (finite contact),
dynamic (the dynamic iCOR, Fig 5.3). The rod: Rod, nanorod().

The same numbers, bit for bit, as ``nanopush icor formulas`` and ``nanopush icor roots``.
"""

from ._nanopush import icor as _icor
from . import _signatures

Rod = _icor.Rod
nanorod = _icor.nanorod
CubicSolution = _icor.CubicSolution
QuasiStaticIcor = _icor.QuasiStaticIcor
cubic_solvers = _icor.cubic_solvers

experimental_fit = _icor.experimental_fit
falvo = _icor.falvo
falvo_normalised = _icor.falvo_normalised
li = _icor.li
li_position = _icor.li_position
unknown_pressure = _icor.unknown_pressure
minimum_force = _icor.minimum_force
known_pressure = _icor.known_pressure
force_from_icor = _icor.force_from_icor
force_unknown_pressure = _icor.force_unknown_pressure
impulsive = _icor.impulsive
constrained_force = _icor.constrained_force
constrained_cubic = _icor.constrained_cubic
constrained_cubic_printed = _icor.constrained_cubic_printed
cubic_roots = _icor.cubic_roots
cubic_branches = _icor.cubic_branches
from_velocity = _icor.from_velocity
line_contact_wrench = _icor.line_contact_wrench
rod_contact_half_width = _icor.rod_contact_half_width
rectangle = _icor.rectangle
dynamic = _icor.dynamic
error_analysis = _icor.error_analysis
thesis_table_5_1 = _icor.thesis_table_5_1

# Signatures inspect.signature reads (the compiled functions carry theirs in the docstring)
# and pybind11's argument conversion failures raised as InputError naming the argument
# (_signatures): the functions, and the classes' methods and constructors
# (inspect.signature(Rod) reads Rod.__init__'s).
for _name, _f in list(globals().items()):
    if not _name.startswith("_") and type(_f).__name__ == "builtin_function_or_method":
        globals()[_name] = _signatures.function(_f, _name)
for _cls in (Rod, CubicSolution, QuasiStaticIcor):
    _signatures.methods(_cls)

__all__ = [n for n in dir() if not n.startswith("_")]
