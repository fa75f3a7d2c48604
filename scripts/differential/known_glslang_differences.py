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
                             r"constant|non-constant global initializer)")


def _line(src, n):
    lines = src.splitlines()
    return lines[n - 1] if 0 < n <= len(lines) else ""


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


def _case_label_type(src, g, c, gok, stage):
    return gok and "case label type does not match switch init-expression type" in c


def _webgl_reserved(src, g, c, gok, stage):
    return gok and bool(re.search(r"'(webgl_|_webgl_)\w*' : (reserved|identifier)|"
                                  r"identifiers (starting with|containing) .*(webgl|__)", c, re.I))


def _double_underscore(src, g, c, gok, stage):
    return gok and "__" in c and ("reserved" in c or "Two consecutive underscores" in c)


def _extension(src, g, c, gok, stage):
    return "#extension" in src and ("extension" in c.lower() or "extension" in g.lower())


def _fragment_output_index(src, g, c, gok, stage):
    return gok and "array indexes for fragment outputs must be constant integral expressions" in c


def _missing_return(src, g, c, gok, stage):
    return gok and "Function does not return a value" in c


def _constant_fold_result(src, g, c, gok, stage):
    return gok and bool(re.search(r"ERROR: .*(Divide by zero|overflow|out of range|undefined)", c))


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
    ("glslang-case-label-type",
     "glslang accepts a case label whose type (int/uint) differs from the switch expression's; "
     "ESSL 3.00 6.2 and ANGLE require the same type",
     _case_label_type),
    ("webgl-reserved-identifier",
     "WebGL reserves identifiers starting with webgl_ or _webgl_; glslang does not",
     _webgl_reserved),
    ("webgl-double-underscore",
     "ANGLE rejects identifiers containing __ for WebGL; GLSL ES only reserves them (glslang warns)",
     _double_underscore),
    ("extension-directive",
     "#extension handling: WebGL 2 exposes its own extension list and treats unknown names per "
     "its own rules; glslang knows a different list",
     _extension),
    ("angle-fragment-output-index",
     "ANGLE requires constant indices into fragment outputs, even vector components; glslang only for arrays",
     _fragment_output_index),
    ("angle-missing-return",
     "ANGLE rejects a non-void function whose end can be reached without a return; glslang accepts",
     _missing_return),
    ("angle-constant-folding-error",
     "ANGLE reports an error for some constant-folding results (division by zero, overflow, "
     "out-of-range shifts); glslang folds them silently",
     _constant_fold_result),
]
REASONS = {name: reason for name, reason, _ in RULES}


def match(src, glslang_log, chromium_log, glslang_ok, stage):
    g = "\n".join(glslang_log)
    for name, _reason, pred in RULES:
        if pred(src, g, chromium_log or "", glslang_ok, stage):
            return name
    return None
