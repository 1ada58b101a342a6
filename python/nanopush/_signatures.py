"""Signatures for the compiled functions, so ``inspect.signature`` (help(), IDEs, Jupyter)
works on every public callable of the package.

pybind11 writes each function's signature as the first line of its docstring
(``friction_wrench(a: object, b: object, ..., sense: int = 1) -> tuple``) but gives the
function no ``__text_signature__``, so ``inspect.signature`` fails on it. Here each compiled
function is wrapped in a plain Python function carrying a ``__signature__`` read from that
line (argument names, defaults, keyword-only markers, annotations kept as text).
"""

import ast as _ast
import functools as _functools
import inspect as _inspect


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


def function(f, name=None, method=False):
    """A Python function calling the compiled `f`, with its signature and docstring (the
    signature line removed from the docstring: help() shows the signature itself). For a
    `method`, the signature starts with self (an overloaded one's reads (self, *args, **kwargs))."""
    name = name or f.__name__
    sig = parse(f.__name__, f.__doc__)
    if method and sig is not None and (not sig.parameters or next(iter(sig.parameters)) != "self"):
        self = _inspect.Parameter("self", _inspect.Parameter.POSITIONAL_ONLY)
        sig = sig.replace(parameters=[self, *sig.parameters.values()])

    @_functools.wraps(f)
    def wrapper(*args, **kwargs):
        return f(*args, **kwargs)

    del wrapper.__wrapped__  # inspect must not look through to the compiled function
    wrapper.__name__ = wrapper.__qualname__ = name
    doc = f.__doc__ or ""
    if sig is not None:
        wrapper.__signature__ = sig
        doc = doc.split("\n", 1)[1].lstrip("\n") if "\n" in doc else ""
    wrapper.__doc__ = doc
    return wrapper


def methods(cls):
    """Give every compiled method and static method of `cls` a signature (in place)."""
    for name, attr in list(vars(cls).items()):
        if name.startswith("__"):
            continue
        if isinstance(attr, staticmethod):
            f = attr.__func__
            if type(f).__name__ == "builtin_function_or_method":
                setattr(cls, name, staticmethod(function(f, name)))
        elif type(attr).__name__ == "instancemethod":
            f = attr.__func__
            w = function(f, name, method=True)
            w.__qualname__ = f"{cls.__name__}.{name}"
            setattr(cls, name, w)
    return cls
