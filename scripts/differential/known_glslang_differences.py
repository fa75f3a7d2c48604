"""Known classes of shaders where glslangValidator's answer differs from Chromium's WebGL2.

Each rule is (name, reason, predicate). A predicate gets (source, glslang's error lines joined,
Chromium's info log, glslang's verdict, stage) and says whether a case where glslang disagrees
with Chromium belongs to the class. `match` returns the first matching rule's name, or None.
The rules were read off the disagreements of run.py (docs/differential.md); a case no rule
explains is counted as unexplained.
"""
import re

# Built-ins glslang 12 does not evaluate in constant expressions (ESSL 3.00 makes every
# built-in except the texture, derivative and noise functions foldable; ANGLE folds them).
GLSLANG_UNFOLDED = ["transpose", "inverse", "matrixCompMult", "outerProduct", "determinant",
                    "floatBitsToInt", "floatBitsToUint", "intBitsToFloat", "uintBitsToFloat",
                    "packSnorm2x16", "unpackSnorm2x16", "packUnorm2x16", "unpackUnorm2x16",
                    "packHalf2x16", "unpackHalf2x16", "sinh", "cosh", "tanh", "asinh", "acosh",
                    "atanh", "atan", "isnan", "isinf", "roundEven", "round", "trunc", "modf",
                    "faceforward", "reflect", "refract", "lessThan", "lessThanEqual", "greaterThan",
                    "greaterThanEqual", "equal", "notEqual", "any", "all", "not", "sign", "fract",
                    "mod", "step", "smoothstep", "mix", "clamp", "min", "max", "abs"]
_UNFOLDED_RE = re.compile(r"\b(%s)\s*\(" % "|".join(GLSLANG_UNFOLDED))
_CONST_INIT_ERR = re.compile(r"ERROR: 0:(\d+): .*(non-constant initializer|global const initializers must be "
                             r"constant|non-constant global initializer|variable indexing fragment shader output)")


def _line(src, n):
    """The source line a compiler calls line n, following `#line` directives."""
    lines = src.splitlines()
    number = {}
    cur = 1
    for k, text in enumerate(lines):
        number.setdefault(cur, k)
        m = re.match(r"\s*#\s*line\s+(\d+)", text)
        cur = int(m.group(1)) if m else cur + 1
    k = number.get(n)
    return lines[k] if k is not None else ""


def _unfolded_builtin(src, g, c, gok, stage):
    m = _CONST_INIT_ERR.search(g)
    if not m or gok:
        return False
    line = _line(src, int(m.group(1)))
    if _UNFOLDED_RE.search(line):
        return True
    # or a `const` it names was initialised with such a call (glslang then reports the use)
    for name in re.findall(r"\b[A-Za-z_]\w*\b", line):
        d = re.search(r"const [^;=]*\b%s\b\s*=([^;]*);" % re.escape(name), src)
        if d and _UNFOLDED_RE.search(d.group(1)):
            return True
    return False


def _switch_decl_only(src, g, c, gok, stage):
    return not gok and "last case/default label not followed by statements" in g


def _webgl_std140(src, g, c, gok, stage):
    return gok and "Only std140 layout is allowed in WebGL" in c


def _builtin_name_redefined(src, g, c, gok, stage):
    return not gok and bool(re.search(r"ERROR: 0:\d+: '(\w+)' : redefinition", g)) and \
        re.search(r"ERROR: 0:\d+: '(\w+)' : redefinition", g).group(1) in _BUILTIN_FUNCS


_BUILTIN_FUNCS = set(GLSLANG_UNFOLDED) | {
    "radians", "degrees", "sin", "cos", "tan", "asin", "acos", "pow", "exp", "log", "exp2", "log2",
    "sqrt", "inversesqrt", "floor", "ceil", "length", "distance", "dot", "cross", "normalize",
    "texture", "textureProj", "textureLod", "textureOffset", "texelFetch", "textureSize",
    "textureGrad", "dFdx", "dFdy", "fwidth"}


def _angle_switch_pruned(src, g, c, gok, stage):
    return gok and "no statement between the last case label" in c


def _invariant_all_fragment(src, g, c, gok, stage):
    return gok and "#pragma STDGL invariant(all) can not be used in fragment shader" in c


def _case_label_type(src, g, c, gok, stage):
    return gok and "case label type does not match switch init-expression type" in c


def _webgl_reserved(src, g, c, gok, stage):
    return gok and bool(re.search(r"'(webgl_|_webgl_)\w*' : (reserved|identifier)|"
                                  r"identifiers (starting with|containing) .*(webgl|__)", c, re.I))


def _extension(src, g, c, gok, stage):
    return gok and "#extension" in src and "extension is not supported" in c


RULES = [
    ("glslang-does-not-fold-builtin",
     "glslang evaluates no constant expression that calls built-ins such as transpose, inverse, "
     "matrixCompMult, sinh, floatBitsToInt or the pack/unpack functions; ESSL 3.00 and ANGLE do",
     _unfolded_builtin),
    ("glslang-switch-case-with-only-declarations",
     "glslang drops declarations that generate no code, so a last case whose statements are only "
     "declarations counts as empty for it; ANGLE counts the declaration as a statement",
     _switch_decl_only),
    ("webgl-std140-only",
     "WebGL 2 allows only std140 uniform blocks; glslang follows GLSL ES, which also allows shared and packed",
     _webgl_std140),
    ("glslang-builtin-name-redefinition",
     "glslang reports a global variable named like a built-in function as a redefinition; "
     "ESSL 3.00 (and ANGLE) let a global name hide the built-in",
     _builtin_name_redefined),
    ("angle-switch-if-false-is-no-statement",
     "ANGLE folds away an `if` whose condition is constant false before checking that the last "
     "case label is followed by a statement; glslang keeps it",
     _angle_switch_pruned),
    ("angle-invariant-all-in-fragment",
     "ANGLE rejects `#pragma STDGL invariant(all)` in a fragment shader; glslang ignores the pragma",
     _invariant_all_fragment),
    ("glslang-case-label-type",
     "glslang accepts a case label whose type (int/uint) differs from the switch expression's; "
     "ESSL 3.00 6.2 and ANGLE require the same type",
     _case_label_type),
    ("webgl-reserved-identifier",
     "WebGL reserves identifiers starting with webgl_ or _webgl_, and ANGLE rejects ones containing __; "
     "glslang accepts them",
     _webgl_reserved),
    ("extension-directive",
     "`#extension NAME : require` for an extension WebGL 2 does not expose (in the data: "
     "GL_EXT_frag_depth, core in ES 3.00) is an error in ANGLE; glslang accepts the directive",
     _extension),
]
REASONS = {name: reason for name, reason, _ in RULES}


def match(src, glslang_log, chromium_log, glslang_ok, stage):
    g = "\n".join(glslang_log)
    for name, _reason, pred in RULES:
        if pred(src, g, chromium_log or "", glslang_ok, stage):
            return name
    return None
