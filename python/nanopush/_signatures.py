"""Signatures for the compiled functions, so ``inspect.signature`` (help(), IDEs, Jupyter)
works on every public callable of the package, and one translation of pybind11's argument
conversion failures into nanopush.InputError.

pybind11 writes each function's signature as the first line of its docstring
(``friction_wrench(a: object, b: object, ..., sense: int = 1) -> tuple``) but gives the
function no ``__text_signature__``, so ``inspect.signature`` fails on it. Here each compiled
function is wrapped in a plain Python function carrying a ``__signature__`` read from that
line (argument names, defaults, keyword-only markers, annotations kept as text).

The same wrapper catches pybind11's "incompatible function arguments" (a TypeError raised
before the function runs: ``engine=3`` where text is expected, ``rod=5``, an array where one
number is) and raises nanopush.InputError naming the argument, its value and what it must be
(docs/errors.md, "Python"), as the arguments the bindings convert themselves do. A call that
matches no signature by its argument names or count (an unknown keyword, a missing argument)
stays a TypeError, as for any Python function.
"""

import ast as _ast
import functools as _functools
import inspect as _inspect
import operator as _operator
import os as _os
import re as _re

from . import _nanopush


class _Shown:
    """A default value pybind11 printed but Python cannot rebuild: shown as printed."""

    def __init__(self, text):
        self.text = text

    def __repr__(self):
        return self.text


def _value(node):
    try:
        return _ast.literal_eval(node)
    except (ValueError, TypeError, SyntaxError):
        return _Shown(_ast.unparse(node))


def parse(name, doc):
    """The inspect.Signature of the first line ``name(...) -> ret`` of a pybind11 docstring,
    or None when the line is not one (an overloaded function's ``(*args, **kwargs)`` is)."""
    first = (doc or "").split("\n", 1)[0].strip()
    if not first.startswith(name + "("):
        return None
    depth, end = 0, None
    for i in range(len(name), len(first)):
        if first[i] in "([{":
            depth += 1
        elif first[i] in ")]}":
            depth -= 1
            if depth == 0:
                end = i
                break
    if end is None:
        return None
    params_text, rest = first[len(name) + 1:end], first[end + 1:].strip()
    try:
        args = _ast.parse(f"def _({params_text}): pass").body[0].args
    except SyntaxError:
        return None
    P = _inspect.Parameter
    params = []
    ann = (lambda a: _ast.unparse(a.annotation) if a.annotation is not None else P.empty)
    positional = args.posonlyargs + args.args
    defaults = [P.empty] * (len(positional) - len(args.defaults)) + [_value(d) for d in args.defaults]
    for a, d in zip(positional, defaults):
        kind = P.POSITIONAL_ONLY if a in args.posonlyargs else P.POSITIONAL_OR_KEYWORD
        params.append(P(a.arg, kind, default=d, annotation=ann(a)))
    if args.vararg:
        params.append(P(args.vararg.arg, P.VAR_POSITIONAL, annotation=ann(args.vararg)))
    for a, d in zip(args.kwonlyargs, args.kw_defaults):
        params.append(P(a.arg, P.KEYWORD_ONLY, default=P.empty if d is None else _value(d), annotation=ann(a)))
    if args.kwarg:
        params.append(P(args.kwarg.arg, P.VAR_KEYWORD, annotation=ann(args.kwarg)))
    ret = rest[2:].strip() if rest.startswith("->") else P.empty
    try:
        return _inspect.Signature(params, return_annotation=ret)
    except ValueError:
        return None


# ---- pybind11's conversion failures as nanopush.InputError -------------------------------

_INCOMPATIBLE = _re.compile(r"^\w+\(\): incompatible (function|constructor) arguments")
_OVERLOAD = _re.compile(r"^\s+\d+\. (.*)$")


def _shown(value):
    """A value as a message shows it: an array by its shape, anything else by its repr (80
    characters at most), as the compiled argument checks do."""
    shape = getattr(value, "shape", None)
    if shape is not None and getattr(value, "ndim", 0) > 0 and not isinstance(value, (str, bytes)):
        return f"an array of shape {tuple(shape)}"
    r = repr(value)
    return r if len(r) <= 80 else r[:77] + "..."


def _real_requirement(value):
    """Why `value` is not one real number (None if it is one)."""
    if isinstance(value, (str, bytes)):
        return "must be a real number (not text)"
    if getattr(value, "ndim", 0) > 0:
        return "must be one value (a number, a NumPy scalar or a 0-d array)"
    if isinstance(value, complex) or getattr(getattr(value, "dtype", None), "kind", "") == "c":
        return "must be a real number (not complex)"
    try:
        float(value)
    except (TypeError, ValueError):
        return "must be a real number"
    return None


def _class_named(text):
    """The package's class of a pybind11 annotation (nanopush._nanopush.icor.Rod), or None."""
    if not text.startswith("nanopush._nanopush."):
        return None
    obj = _nanopush
    for part in text.split(".")[2:]:
        obj = getattr(obj, part, None)
        if obj is None:
            return None
    return obj if isinstance(obj, type) else None


def _split_top(text):
    """"a, b[c, d], e" -> ["a", "b[c, d]", "e"] (commas outside brackets)."""
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        if ch in "[(":
            depth += 1
        elif ch in "])":
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    parts.append(text[start:].strip())
    return parts


def requirement(annotation, value):
    """What `value` must be to pass as a pybind11 argument annotated `annotation` (its
    signature's text), or None when it looks fine (or the annotation is not understood)."""
    if not isinstance(annotation, str) or annotation in ("object", "handle", "Any"):
        return None
    m = _re.fullmatch(r"Optional\[(.*)\]", annotation)
    if m:
        return None if value is None else requirement(m.group(1), value)
    if annotation == "str":
        return None if isinstance(value, str) else "must be text"
    if annotation == "os.PathLike":
        return None if isinstance(value, (str, bytes, _os.PathLike)) else "must be a path (text or os.PathLike)"
    if annotation == "bytes":
        return None if isinstance(value, bytes) else "must be bytes"
    if annotation == "bool":
        return None if isinstance(value, bool) or type(value).__name__ == "bool_" else "must be True or False"
    if annotation == "float":
        return _real_requirement(value)
    if annotation == "int":
        if isinstance(value, (str, bytes)):
            return "must be a whole number (not text)"
        try:
            _operator.index(value)
        except TypeError:
            return "must be a whole number"
        return "must be a whole number in the range of the argument's integer type"
    if annotation in ("dict", "list", "tuple"):
        kind = {"dict": dict, "list": list, "tuple": tuple}[annotation]
        return None if isinstance(value, kind) else f"must be a {annotation}"
    m = _re.fullmatch(r"(?:List|Sequence)\[(.*)\]", annotation)
    if m:
        inner, count = m.group(1), None
        n = _re.fullmatch(r"(.*)\[(\d+)\]", inner)  # std::array<T, N>: T[N]
        if n:
            inner, count = n.group(1), int(n.group(2))
        if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__len__") or not hasattr(value, "__iter__"):
            return f"must be a sequence of {count or 'any number of'} values"
        if count is not None and len(value) != count:
            return f"must be {count} values (it has {len(value)})"
        for k, item in enumerate(value):
            why = requirement(inner, item)
            if why:
                return f"element {k} = {_shown(item)}: {why}"
        return None
    m = _re.fullmatch(r"Dict\[(.*)\]", annotation)
    if m:
        if not isinstance(value, dict):
            return "must be a dict"
        parts = _split_top(m.group(1))
        if len(parts) == 2:
            for k, v in value.items():
                why = requirement(parts[0], k) or requirement(parts[1], v)
                if why:
                    return f"entry {k!r:.40}: {why}"
        return None
    cls = _class_named(annotation)
    if cls is not None:
        public = annotation.replace("nanopush._nanopush.", "nanopush.")
        return None if isinstance(value, cls) else f"must be a {public}"
    return None  # numpy.ndarray[...] and the rest: pybind11 converts or not; not judged here


def _overloads(message, name, constructor):
    """The signatures pybind11 lists in its "incompatible ... arguments" message."""
    sigs = []
    for line in message.splitlines()[1:]:
        if line.startswith("Invoked with"):
            break
        m = _OVERLOAD.match(line)
        if not m:
            continue
        text = m.group(1)
        if constructor:  # "nanopush._nanopush.icor.Rod(length: float = ..., ...)": self first
            inner = text[text.index("(") + 1:text.rindex(")")]
            text = f"({'self, ' + inner if inner.strip() else 'self'}) -> None"
        sig = parse(name, name + text)
        if sig is not None:
            sigs.append(sig)
    return sigs


def translated(error, name, args, kwargs):
    """The nanopush.InputError for pybind11's TypeError `error` from calling `name`(*args,
    **kwargs): the first argument whose value does not fit its annotation, in the first
    signature the call binds to. A call that binds to no signature (argument names or counts)
    is a TypeError, as for a Python function: with Python's words for it where there is one
    signature, else None (pybind11's own TypeError stands)."""
    message = str(error)
    m = _INCOMPATIBLE.match(message)
    if not m:
        return None
    constructor = m.group(1) == "constructor"
    sigs = _overloads(message, name, constructor)
    P = _inspect.Parameter
    bound_any, why_not = False, []
    for sig in sigs:
        try:
            bound = sig.bind(*args, **kwargs)
        except TypeError as e:
            why_not.append(str(e))
            continue
        bound_any = True
        for pname, value in bound.arguments.items():
            param = sig.parameters[pname]
            if param.kind in (P.VAR_POSITIONAL, P.VAR_KEYWORD) or pname == "self":
                continue
            why = requirement(param.annotation, value)
            if why:
                e = _nanopush.InputError(f"{pname} = {_shown(value)}: {why}")
                e.field, e.index = pname, None
                return e
    if not bound_any:  # Python's own words for the call, as for a Python function
        if len(why_not) != 1:
            return None
        shown = (type(args[0]).__name__ + "()") if constructor and args else f"{name}()"
        return TypeError(f"{shown}: {why_not[0]}")
    # The arguments bind, but which one pybind11 refused is not clear: what it takes.
    takes = " or ".join(f"({', '.join(str(p) for p in sig.parameters.values())})" for sig in sigs)
    e = _nanopush.InputError(f"{name}(): an argument of a type it does not take; it takes {takes}")
    e.field, e.index = "", None
    return e


# ---- wrappers ---------------------------------------------------------------------------


def function(f, name=None, method=False):
    """A Python function calling the compiled `f`, with its signature and docstring (the
    signature line removed from the docstring: help() shows the signature itself), and
    pybind11's argument conversion failures raised as nanopush.InputError (translated). For a
    `method`, the signature starts with self (an overloaded one's reads (self, *args, **kwargs))."""
    name = name or f.__name__
    sig = parse(f.__name__, f.__doc__)
    if method and sig is not None and (not sig.parameters or next(iter(sig.parameters)) != "self"):
        self = _inspect.Parameter("self", _inspect.Parameter.POSITIONAL_ONLY)
        sig = sig.replace(parameters=[self, *sig.parameters.values()])

    @_functools.wraps(f)
    def wrapper(*args, **kwargs):
        try:
            return f(*args, **kwargs)
        except TypeError as error:
            replacement = translated(error, f.__name__, args, kwargs)
            if replacement is None:
                raise
            raise replacement from None

    del wrapper.__wrapped__  # inspect must not look through to the compiled function
    wrapper.__name__ = wrapper.__qualname__ = name
    doc = f.__doc__ or ""
    if sig is not None:
        wrapper.__signature__ = sig
        doc = doc.split("\n", 1)[1].lstrip("\n") if "\n" in doc else ""
    wrapper.__doc__ = doc
    return wrapper


def module(mod):
    """Wrap every compiled function of the extension module `mod` in place (function): the
    package's own calls (nanopush.run calls _nanopush._run) convert their failures too."""
    for name, attr in list(vars(mod).items()):
        if type(attr).__name__ == "builtin_function_or_method":
            setattr(mod, name, function(attr, name))
    return mod


def _setter(fset, name):
    """A compiled attribute setter (`rod.length = ...`) with its conversion failure raised as
    nanopush.InputError naming the attribute."""

    def wrapper(self, value):
        try:
            fset(self, value)
        except TypeError as error:
            m = _re.search(r"arg0: ([^)]*)\) -> None", str(error))
            if not str(error).startswith("(): incompatible function arguments") or not m:
                raise
            why = requirement(m.group(1).strip(), value) or f"must be of the type {m.group(1).strip()}"
            e = _nanopush.InputError(f"{name} = {_shown(value)}: {why}")
            e.field, e.index = name, None
            raise e from None

    wrapper.__name__ = name
    return wrapper


def methods(cls):
    """Give every compiled method, static method and constructor (__init__, so that
    inspect.signature(cls) works) of `cls` a signature, and the translation to every method
    and attribute setter (in place)."""
    for name, attr in list(vars(cls).items()):
        if name.startswith("__") and name != "__init__":
            continue
        if isinstance(attr, property) and type(attr.fset).__name__ in ("builtin_function_or_method", "instancemethod"):
            setattr(cls, name, property(attr.fget, _setter(attr.fset, name), attr.fdel, attr.__doc__))
        elif isinstance(attr, staticmethod):
            f = attr.__func__
            if type(f).__name__ == "builtin_function_or_method":
                setattr(cls, name, staticmethod(function(f, name)))
        elif type(attr).__name__ == "instancemethod":
            f = attr.__func__
            w = function(f, name, method=True)
            w.__qualname__ = f"{cls.__name__}.{name}"
            setattr(cls, name, w)
    return cls
