"""A small, safe evaluator for the formulas users type: ``3*cos(t)``, ``2*pi``, ``x*y/4``.

The text is parsed with :func:`ast.parse` and checked against a whitelist; the accepted tree is
turned into a tree of plain Python closures. Nothing is ever passed to ``eval``, ``exec`` or
``compile``, so no attribute, name or call outside the list below can be reached.

Allowed: numbers (``2``, ``0.5``, ``1e-3``), the caller's variables (``t``, or ``x`` and ``y``),
the constants ``pi`` and ``e``, ``+ - * / **``, unary ``-`` and ``+``, parentheses and the
functions ``sin cos tan sqrt exp log abs`` (one argument each; ``log`` is the natural log).

Limits (each refusal is a :class:`ValueError` with a one-line message naming the rule):

* at most :data:`MAX_LENGTH` characters and :data:`MAX_BRACKETS` nested brackets, both checked
  *before* parsing, so neither the parser nor the checker can run out of stack or memory;
* at most :data:`MAX_DEPTH` nested operations in the parsed tree;
* a constant exponent must satisfy ``|exponent| <= MAX_EXPONENT`` (so ``9**9**9`` is refused at
  once) and a constant sub-expression must be a finite float.

Evaluation (:meth:`Expr.__call__`) is in float64: scalar values through :mod:`math` (no numpy
needed: the exam answers run where numpy is not installed, in the browser), numpy arrays (one
value per sample or per pixel) through numpy ufuncs, imported then. **Domain errors are errors**: a result that
is not finite (``log(-1)``, ``sqrt(-1)``, ``1/0``, an overflowing ``**``) raises ``ValueError``
naming the expression and the first variable values where it happens; nothing returns NaN.

Polynomial and rational expressions (no function other than ``abs``, no ``pi``/``e``, integer
constant exponents) can also be evaluated exactly with :meth:`Expr.exact`, over
:class:`fractions.Fraction`; :func:`parse_exact` uses it for command-line values, so
``--t-range 0 1/3`` stays exact while ``--t-range 0 2*pi`` becomes a float.

>>> f = compile_expr("3*cos(t) + t**2", ("t",))
>>> f(t=0.0)
3.0
>>> compile_expr("__import__('os')", ("t",))
Traceback (most recent call last):
...
ValueError: expression "__import__('os')": function '__import__' is not allowed (allowed: sin, cos, tan, sqrt, exp, log, abs)
"""

from __future__ import annotations

import ast
import math
import operator
from collections.abc import Callable
from fractions import Fraction
from typing import Any

MAX_LENGTH = 500
"""Longest accepted expression, in characters."""

MAX_BRACKETS = 50
"""Deepest accepted bracket nesting, checked on the text before parsing."""

MAX_DEPTH = 200
"""Deepest accepted nesting of operations in the parsed tree."""

MAX_EXPONENT = 100
"""Largest accepted magnitude of a constant exponent."""

MAX_BITS = 4096
"""Largest numerator or denominator (in bits) of an exact intermediate value."""

FUNCTIONS: dict[str, Callable[[Any], Any]] = {
    "sin": math.sin,
    "cos": math.cos,
    "tan": math.tan,
    "sqrt": math.sqrt,
    "exp": math.exp,
    "log": math.log,
    "abs": abs,
}
"""The callable functions, by name (for a scalar; :func:`_array_ops` holds their numpy ufuncs)."""

CONSTANTS: dict[str, float] = {"pi": math.pi, "e": math.e}
"""The named constants."""

_BINOPS: dict[type, str] = {
    ast.Add: "+",
    ast.Sub: "-",
    ast.Mult: "*",
    ast.Div: "/",
    ast.Pow: "**",
}

Ops = dict[str, Callable[..., Any]]
"""The operations a compiled expression calls, by name: the functions, the binary operators
and ``neg``; one table for scalars (:data:`_SCALAR_OPS`), one for arrays (:func:`_array_ops`)."""


def _power(x: float, y: float) -> float:
    """``x ** y`` in float64 as numpy's ``power`` gives it for a scalar exponent: ``x * x``
    for 2, ``sqrt(x)`` for 1/2, ``1 / x`` for -1 (each correctly rounded, where ``pow`` may be
    half an ulp off), ``pow`` otherwise; so a formula has the same value with numpy or without.

    >>> _power(3.0, 2.0), _power(4.0, 0.5), _power(4.0, -1.0), _power(2.0, 10.0)
    (9.0, 2.0, 0.25, 1024.0)
    """
    if y == 2.0:
        return x * x
    if y == 0.5:
        return math.sqrt(x)
    if y == -1.0:
        return 1.0 / x
    return math.pow(x, y)


_SCALAR_OPS: Ops = {
    **FUNCTIONS,
    "neg": operator.neg,
    "+": operator.add,
    "-": operator.sub,
    "*": operator.mul,
    "/": operator.truediv,
    "**": _power,
}
"""Scalar float64 arithmetic: :mod:`math` raises where numpy would give NaN or infinity
(``log(-1)``, ``1/0``, ``exp(1000)``); both are the same domain error."""

_SCALAR_ERRORS = (ValueError, ZeroDivisionError, OverflowError)

_ARRAY_OPS: Ops = {}


def _array_ops() -> Ops:
    """The numpy ufuncs of every operation, imported on the first array evaluation."""
    if not _ARRAY_OPS:
        import numpy as np

        _ARRAY_OPS.update(
            sin=np.sin, cos=np.cos, tan=np.tan, sqrt=np.sqrt, exp=np.exp, log=np.log, abs=np.abs
        )
        _ARRAY_OPS.update({"neg": np.negative, "+": np.add, "-": np.subtract, "*": np.multiply})
        _ARRAY_OPS.update({"/": np.divide, "**": np.power})
    return _ARRAY_OPS


_EXACT_BINOPS: dict[str, Callable[[Fraction, Fraction], Fraction]] = {
    "+": lambda a, b: a + b,
    "-": lambda a, b: a - b,
    "*": lambda a, b: a * b,
}

#: Operators Python parses but the whitelist refuses, with the message's name for them.
_REFUSED_OPS = {
    ast.Mod: "'%'",
    ast.FloorDiv: "'//'",
    ast.MatMult: "'@'",
    ast.LShift: "'<<'",
    ast.RShift: "'>>'",
    ast.BitOr: "'|'",
    ast.BitAnd: "'&'",
    ast.BitXor: "'^'",
    ast.Invert: "'~'",
    ast.Not: "'not'",
}

#: Node types refused outright, with the message naming them.
_REFUSED_NODES: dict[type, str] = {
    ast.Attribute: "attribute access is not allowed",
    ast.Subscript: "subscripts are not allowed",
    ast.Slice: "slices are not allowed",
    ast.Lambda: "lambda is not allowed",
    ast.ListComp: "comprehensions are not allowed",
    ast.SetComp: "comprehensions are not allowed",
    ast.DictComp: "comprehensions are not allowed",
    ast.GeneratorExp: "comprehensions are not allowed",
    ast.Compare: "comparisons are not allowed",
    ast.BoolOp: "'and'/'or' are not allowed",
    ast.IfExp: "conditional expressions are not allowed",
    ast.NamedExpr: "assignment is not allowed",
    ast.Tuple: "tuples are not allowed",
    ast.List: "lists are not allowed",
    ast.Dict: "dicts are not allowed",
    ast.Set: "sets are not allowed",
    ast.Starred: "'*' unpacking is not allowed",
    ast.JoinedStr: "strings are not allowed",
    ast.Await: "await is not allowed",
    ast.Yield: "yield is not allowed",
    ast.YieldFrom: "yield is not allowed",
}


def _shown(text: str) -> str:
    """The expression as an error message quotes it: on one line, cut to 40 characters."""
    s = " ".join(text.split())
    return repr(s if len(s) <= 40 else s[:37] + "...")


class _Node:
    """One operation of a compiled expression.

    ``value(env, ops)`` evaluates in float64 with ``ops`` (:data:`Ops`: math for a scalar, numpy
    ufuncs for arrays); ``exact(env)`` over Fractions (only called when
    :attr:`rational` is true). ``const`` is the float value of a constant sub-expression.
    """

    __slots__ = ("const", "exact", "rational", "value")

    def __init__(
        self,
        value: Callable[[dict[str, Any], Ops], Any],
        exact: Callable[[dict[str, Fraction]], Fraction] | None,
        const: float | None = None,
    ) -> None:
        self.value = value
        self.exact = exact
        self.rational = exact is not None
        self.const = const


def _bounded(v: Fraction) -> Fraction:
    if v.numerator.bit_length() > MAX_BITS or v.denominator.bit_length() > MAX_BITS:
        raise ValueError(f"exact value too large (more than {MAX_BITS} bits)")
    return v


def _exact_div(a: Fraction, b: Fraction) -> Fraction:
    if b == 0:
        raise ZeroDivisionError
    return a / b


class Expr:
    """A checked expression in the caller's variables; call it with keyword values.

    >>> f = compile_expr("x*y/4 + 1", ("x", "y"))
    >>> f(x=2.0, y=6.0), f.text, f.variables
    (4.0, 'x*y/4 + 1', ('x', 'y'))
    >>> import numpy as np
    >>> f(x=np.array([0.0, 2.0]), y=2.0)
    array([1., 2.])
    >>> f.exact(x=1, y=1)
    Fraction(5, 4)
    >>> compile_expr("log(t)", ("t",))(t=-1.0)
    Traceback (most recent call last):
    ...
    ValueError: expression 'log(t)' is undefined or infinite at t = -1
    """

    __slots__ = ("_names", "_root", "rational", "size", "text", "variables")

    def __init__(self, text: str, variables: tuple[str, ...], root: _Node, size: int = 1) -> None:
        self.text = text
        """The expression as given."""
        self.variables = variables
        """The names it may use, in the caller's order."""
        self._names = frozenset(variables)
        self.rational = root.rational
        """True if :meth:`exact` can evaluate it (rational operations only)."""
        self._root = root
        self.size = size
        """Operations, names and numbers in the parsed formula: the work of one evaluation
        (``x*y + 1``: 5)."""

    def __repr__(self) -> str:
        return f"Expr({self.text!r}, {self.variables!r})"

    def _env(self, values: dict[str, Any]) -> None:
        missing = [v for v in self.variables if v not in values]
        unknown = [k for k in values if k not in self.variables]
        if missing or unknown:
            raise TypeError(
                f"expression {_shown(self.text)} takes {', '.join(self.variables) or 'no variables'}"
                f" (missing: {', '.join(missing) or '-'}; unexpected: {', '.join(unknown) or '-'})"
            )

    def __call__(self, **values: Any) -> Any:
        """Evaluate in float64: a ``float`` for scalar values, an array if any value is one.

        Raises ``ValueError`` if any result is not finite (domain error, division by zero,
        overflow).
        """
        if values.keys() != self._names:
            self._env(values)  # raises TypeError naming what is missing or unexpected
        if all(isinstance(v, (int, float, Fraction)) for v in values.values()):
            return self._scalar({k: float(v) for k, v in values.items()})
        import numpy as np

        env = {k: np.asarray(v, dtype=np.float64) for k, v in values.items()}
        with np.errstate(all="ignore"):
            out = np.asarray(self._root.value(env, _array_ops()), dtype=np.float64)
        if env:
            shape = np.broadcast_shapes(*(a.shape for a in env.values()))
            if out.shape != shape:
                out = np.array(np.broadcast_to(out, shape))
        finite = np.isfinite(out)
        if not finite.all():
            where = np.unravel_index(int(np.argmin(finite)), out.shape) if out.shape else ()
            at = ", ".join(
                f"{k} = {float(np.broadcast_to(a, out.shape)[where]):.6g}" for k, a in env.items()
            )
            raise ValueError(
                f"expression {_shown(self.text)} is undefined or infinite"
                + (f" at {at}" if at else "")
            )
        if out.shape == ():
            return float(out)
        return out

    def _scalar(self, env: dict[str, float]) -> float:
        """Evaluate at scalar values through :mod:`math` (no numpy)."""
        try:
            out = float(self._root.value(env, _SCALAR_OPS))
        except _SCALAR_ERRORS:
            out = math.nan
        if not math.isfinite(out):
            at = ", ".join(f"{k} = {v:.6g}" for k, v in env.items())
            raise ValueError(
                f"expression {_shown(self.text)} is undefined or infinite"
                + (f" at {at}" if at else "")
            )
        return out

    def exact(self, **values: int | Fraction) -> Fraction:
        """Evaluate exactly over Fractions; ``ValueError`` if the expression is not rational."""
        if not self.rational or self._root.exact is None:
            raise ValueError(
                f"expression {_shown(self.text)} cannot be evaluated exactly "
                "(it uses pi, e, a function other than abs, or a non-integer power)"
            )
        self._env(values)
        env = {k: Fraction(v) for k, v in values.items()}
        at = (" at " + ", ".join(f"{k} = {v}" for k, v in env.items())) if env else ""
        try:
            return self._root.exact(env)
        except ZeroDivisionError:
            raise ValueError(f"expression {_shown(self.text)} divides by zero{at}") from None
        except ValueError as err:
            raise ValueError(f"expression {_shown(self.text)}: {err}{at}") from None


def compile_expr(text: str, variables: tuple[str, ...]) -> Expr:
    """Check ``text`` against the whitelist and compile it over ``variables``.

    Raises ``ValueError`` with one line naming what is refused.

    >>> compile_expr("t.real", ("t",))
    Traceback (most recent call last):
    ...
    ValueError: expression 't.real': attribute access is not allowed
    >>> compile_expr("9**9**9", ("t",))
    Traceback (most recent call last):
    ...
    ValueError: expression '9**9**9': exponent 387420489 is too large (|exponent| <= 100)
    """
    for v in variables:
        if not v.isidentifier() or v in FUNCTIONS or v in CONSTANTS:
            raise ValueError(f"bad variable name {v!r}")
    if not isinstance(text, str):
        raise ValueError("expression must be a string")
    shown = _shown(text)
    if len(text) > MAX_LENGTH:
        raise ValueError(f"expression too long ({len(text)} characters; at most {MAX_LENGTH})")
    depth = deepest = 0
    for ch in text:
        if ch in "([{":
            depth += 1
            deepest = max(deepest, depth)
        elif ch in ")]}":
            depth -= 1
    if deepest > MAX_BRACKETS:
        raise ValueError(
            f"expression {shown} is too deeply nested ({deepest} brackets; at most {MAX_BRACKETS})"
        )
    if not text.strip():
        raise ValueError("empty expression")
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except (SyntaxError, ValueError):
        raise ValueError(f"expression {shown} is not a valid formula") from None
    except (RecursionError, MemoryError):
        raise ValueError(f"expression {shown} is too deeply nested") from None
    _check_depth(tree, shown)
    root = _Compiler(variables, shown).node(tree.body)
    size = sum(1 for n in ast.walk(tree.body) if isinstance(n, ast.expr))
    return Expr(text, tuple(variables), root, size)


def _check_depth(tree: ast.AST, shown: str) -> None:
    """Refuse trees deeper than :data:`MAX_DEPTH` (iteratively: no recursion to blow up)."""
    stack: list[tuple[ast.AST, int]] = [(tree, 0)]
    while stack:
        node, d = stack.pop()
        if d > MAX_DEPTH:
            raise ValueError(
                f"expression {shown} is too deeply nested (more than {MAX_DEPTH} levels)"
            )
        stack.extend((child, d + 1) for child in ast.iter_child_nodes(node))


class _Compiler:
    """Turns a checked ``ast`` tree into :class:`_Node` closures, refusing anything else."""

    def __init__(self, variables: tuple[str, ...], shown: str) -> None:
        self.variables = variables
        self.shown = shown

    def refuse(self, what: str) -> ValueError:
        return ValueError(f"expression {self.shown}: {what}")

    def node(self, n: ast.AST) -> _Node:
        if isinstance(n, ast.Constant):
            return self.constant(n.value)
        if isinstance(n, ast.Name):
            return self.name(n.id)
        if isinstance(n, ast.UnaryOp):
            return self.unary(n)
        if isinstance(n, ast.BinOp):
            return self.binop(n)
        if isinstance(n, ast.Call):
            return self.call(n)
        raise self.refuse(_REFUSED_NODES.get(type(n), f"{type(n).__name__} is not allowed"))

    def constant(self, value: Any) -> _Node:
        if isinstance(value, bool) or value is None or value is Ellipsis:
            raise self.refuse(f"{value!r} is not allowed")
        if isinstance(value, (str, bytes)):
            raise self.refuse("strings are not allowed")
        if isinstance(value, complex):
            raise self.refuse("complex numbers are not allowed")
        try:
            f = float(value)
        except OverflowError:
            raise self.refuse("number too large") from None
        if not math.isfinite(f):
            raise self.refuse("number too large")
        q = Fraction(value) if isinstance(value, int) else Fraction(repr(value))
        return _Node(lambda env, ops: f, lambda env: q, const=f)

    def name(self, ident: str) -> _Node:
        if ident in self.variables:
            return _Node(lambda env, ops: env[ident], lambda env: env[ident])
        if ident in CONSTANTS:
            c = CONSTANTS[ident]
            return _Node(lambda env, ops: c, None, const=c)
        if ident in FUNCTIONS:
            raise self.refuse(f"function {ident!r} must be called, as in {ident}(t)")
        allowed = ", ".join((*self.variables, *CONSTANTS))
        raise self.refuse(f"unknown name {ident!r} (allowed: {allowed})")

    def unary(self, n: ast.UnaryOp) -> _Node:
        if not isinstance(n.op, (ast.USub, ast.UAdd)):
            raise self.refuse(f"operator {_REFUSED_OPS.get(type(n.op), '?')} is not allowed")
        child = self.node(n.operand)
        if isinstance(n.op, ast.UAdd):
            return child
        cv, ce = child.value, child.exact
        node = _Node(
            lambda env, ops: ops["neg"](cv(env, ops)),
            None if ce is None else (lambda env: -ce(env)),
        )
        return self.fold(node, child)

    def binop(self, n: ast.BinOp) -> _Node:
        if type(n.op) not in _BINOPS:
            hint = " (use ** for powers)" if isinstance(n.op, ast.BitXor) else ""
            raise self.refuse(f"operator {_REFUSED_OPS.get(type(n.op), '?')} is not allowed{hint}")
        symbol = _BINOPS[type(n.op)]
        left, right = self.node(n.left), self.node(n.right)
        lv, rv, le, re_ = left.value, right.value, left.exact, right.exact
        exact: Callable[[dict[str, Fraction]], Fraction] | None = None
        if symbol == "**":
            if right.const is not None and abs(right.const) > MAX_EXPONENT:
                raise self.refuse(
                    f"exponent {_fmt_const(right.const)} is too large (|exponent| <= {MAX_EXPONENT})"
                )
            if le is not None and right.const is not None and right.const.is_integer():
                power = int(right.const)

                def exact(env: dict[str, Fraction]) -> Fraction:
                    base = le(env)
                    bits = max(base.numerator.bit_length(), base.denominator.bit_length())
                    if bits * abs(power) > MAX_BITS:
                        raise ValueError(f"exact value too large (more than {MAX_BITS} bits)")
                    return base**power

        elif le is not None and re_ is not None:
            op = _exact_div if symbol == "/" else _EXACT_BINOPS[symbol]

            def exact(env: dict[str, Fraction]) -> Fraction:
                return _bounded(op(le(env), re_(env)))

        node = _Node(lambda env, ops: ops[symbol](lv(env, ops), rv(env, ops)), exact)
        return self.fold(node, left, right)

    def call(self, n: ast.Call) -> _Node:
        if not isinstance(n.func, ast.Name):
            if isinstance(n.func, ast.Attribute):
                raise self.refuse("attribute access is not allowed")
            raise self.refuse("only calls of sin, cos, tan, sqrt, exp, log, abs are allowed")
        fname = n.func.id
        if fname not in FUNCTIONS:
            raise self.refuse(
                f"function {fname!r} is not allowed (allowed: {', '.join(FUNCTIONS)})"
            )
        if n.keywords or len(n.args) != 1 or isinstance(n.args[0], ast.Starred):
            raise self.refuse(f"{fname}() takes exactly one argument")
        arg = self.node(n.args[0])
        av, ae = arg.value, arg.exact
        exact = None
        if fname == "abs" and ae is not None:

            def exact(env: dict[str, Fraction]) -> Fraction:
                return abs(ae(env))

        return self.fold(_Node(lambda env, ops: ops[fname](av(env, ops)), exact), arg)

    def fold(self, node: _Node, *children: _Node) -> _Node:
        """Evaluate a constant sub-expression now; refuse it if it is not a finite float."""
        if any(c.const is None for c in children):
            return node
        try:
            value = float(node.value({}, _SCALAR_OPS))
        except _SCALAR_ERRORS:
            value = math.nan
        if not math.isfinite(value):
            raise self.refuse("a constant part is undefined or too large")
        q: Fraction | None = None
        if node.exact is not None:
            try:
                q = node.exact({})
            except (ValueError, ZeroDivisionError):
                q = None
        exact = None if q is None else (lambda env, q=q: q)
        return _Node(lambda env, ops: value, exact, const=value)


def _fmt_const(v: float) -> str:
    return str(int(v)) if v.is_integer() else repr(v)


def parse_value(text: str) -> float:
    """A constant expression given on the command line, as a float: ``2*pi``, ``-3``, ``1/3``.

    >>> parse_value("2*pi")
    6.283185307179586
    >>> parse_value("t")
    Traceback (most recent call last):
    ...
    ValueError: expression 't': unknown name 't' (allowed: pi, e)
    """
    return float(compile_expr(text, ())())


def parse_exact(text: str) -> Fraction | float:
    """A constant expression, exactly when it is rational: ``1/3`` -> Fraction, ``pi`` -> float.

    >>> parse_exact("1/3"), parse_exact("-3"), parse_exact("pi/2")
    (Fraction(1, 3), Fraction(-3, 1), 1.5707963267948966)
    """
    expr = compile_expr(text, ())
    if expr.rational:
        return expr.exact()
    return float(expr())
