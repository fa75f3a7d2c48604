#!/usr/bin/env python3
"""Random GLSL ES 3.00 shaders from the grammar, mostly valid, some deliberately broken.

usage: gen.py --seed S --count N --out DIR [--mutate-rate R] [--start I]

Every shader is a function of (seed, index) alone: `generate(seed, index)` returns
(stage, source, mutations); the file is DIR/s{seed}_{index:06d}.{frag,vert}. A mutated
shader carries one (sometimes two) deliberate faults, named in a comment on the line after #version
`// mutations: a,b` (an empty list means the generator meant it to be valid).
Standard library only.
"""
import argparse
import os
import random

FLOAT_VEC = {1: "float", 2: "vec2", 3: "vec3", 4: "vec4"}
INT_VEC = {1: "int", 2: "ivec2", 3: "ivec3", 4: "ivec4"}
UINT_VEC = {1: "uint", 2: "uvec2", 3: "uvec3", 4: "uvec4"}
BOOL_VEC = {1: "bool", 2: "bvec2", 3: "bvec3", 4: "bvec4"}
VECS = {"float": FLOAT_VEC, "int": INT_VEC, "uint": UINT_VEC, "bool": BOOL_VEC}
INFO = {}  # type name -> (base, size) for scalars/vectors; ('mat', cols, rows) for matrices
for _b, _m in VECS.items():
    for _n, _t in _m.items():
        INFO[_t] = (_b, _n)
MATS = {}
for _c in (2, 3, 4):
    for _r in (2, 3, 4):
        _name = "mat%d" % _c if _c == _r else "mat%dx%d" % (_c, _r)
        MATS[_name] = (_c, _r)
MAT_ALIASES = {"mat2x2": "mat2", "mat3x3": "mat3", "mat4x4": "mat4"}
SCALAR_VEC = list(INFO)
NUMERIC = [t for t in SCALAR_VEC if INFO[t][0] != "bool"]
GEN_F = list(FLOAT_VEC.values())
GEN_I = list(INT_VEC.values())
GEN_U = list(UINT_VEC.values())
GEN_B = list(BOOL_VEC.values())
SAMPLERS = {  # sampler type -> (coord type, texelFetch coord, size result, result type)
    "sampler2D": ("vec2", "ivec2", "ivec2", "vec4"),
    "sampler3D": ("vec3", "ivec3", "ivec3", "vec4"),
    "samplerCube": ("vec3", None, "ivec2", "vec4"),
    "sampler2DArray": ("vec3", "ivec3", "ivec3", "vec4"),
    "isampler2D": ("vec2", "ivec2", "ivec2", "ivec4"),
    "usampler2D": ("vec2", "ivec2", "ivec2", "uvec4"),
}
NEEDS_SAMPLER_PRECISION = {"sampler3D", "sampler2DArray", "isampler2D", "usampler2D"}
PREC = ["lowp", "mediump", "highp"]

# precedence levels (higher binds tighter)
P_COMMA, P_ASSIGN, P_COND, P_OR, P_XOR, P_AND, P_BOR, P_BXOR, P_BAND, P_EQ, P_REL, P_SHIFT, \
    P_ADD, P_MUL, P_UNARY, P_POSTFIX, P_PRIMARY = range(1, 18)
BIN_PREC = {"||": P_OR, "^^": P_XOR, "&&": P_AND, "|": P_BOR, "^": P_BXOR, "&": P_BAND,
            "==": P_EQ, "!=": P_EQ, "<": P_REL, ">": P_REL, "<=": P_REL, ">=": P_REL,
            "<<": P_SHIFT, ">>": P_SHIFT, "+": P_ADD, "-": P_ADD, "*": P_MUL, "/": P_MUL, "%": P_MUL}

MUTATIONS = [
    "type_mismatch", "undeclared", "builtin_arity", "builtin_argtype", "ctor_arity", "lvalue",
    "const_write", "readonly_write", "missing_return", "bad_swizzle", "index_oob", "redeclare",
    "break_outside", "return_mismatch", "reserved_name", "discard_vertex", "bad_io_type",
    "uniform_init", "nonconst_size", "switch_error", "no_precision", "bad_condition",
    "call_error", "extension", "mixed_arith", "stage_builtin", "literal_range", "array_of_array",
    "bad_precision_stmt", "layout_error", "gl_fragcolor", "overload_return", "redefine_builtin",
    "macro_error", "ternary_mismatch", "sampler_no_precision", "out_arg_not_lvalue", "scalar_swizzle",
]


class Var:
    def __init__(self, name, type_, array=None, const=False, readonly=False, const_index=False):
        self.name, self.type, self.array, self.const_index = name, type_, array, const_index
        self.const, self.readonly = const, readonly


class Func:
    def __init__(self, name, ret, params):
        self.name, self.ret, self.params = name, ret, params  # params: [(qual, type, name)]


class Gen:
    def __init__(self, rng, stage, mutations):
        self.r = rng
        self.stage = stage
        self.mut = list(mutations)
        self.scopes = [{}]
        self.structs = {}  # name -> [(type, name, array)]
        self.funcs = []
        self.counter = 0
        self.globals = []
        self.loop_depth = 0
        self.switch_depth = 0
        self.cur_ret = None
        self.frag_outs = []
        self.used_mutations = []
        self.samplers = []

    # ----------------------------------------------------------------- helpers
    def name(self, prefix="v"):
        self.counter += 1
        return "%s%d" % (prefix, self.counter)

    def chance(self, p):
        return self.r.random() < p

    def take(self, kind):
        """True once if this shader should carry mutation `kind` here."""
        if kind in self.mut:
            self.mut.remove(kind)
            self.used_mutations.append(kind)
            return True
        return False

    def declare(self, var):
        self.scopes[-1][var.name] = var

    def all_vars(self):
        seen = {}
        for s in self.scopes:
            seen.update(s)
        return list(seen.values())

    def vars_of(self, t, writable=False, nonconst=False):
        out = []
        for v in self.all_vars():
            if v.array is not None:
                continue
            if v.type == t and (not writable or not (v.const or v.readonly)) \
                    and (not nonconst or not v.const):
                out.append(v)
        return out

    def array_vars(self, t, writable=False):
        return [v for v in self.all_vars() if v.array is not None and v.type == t
                and (not writable or not (v.const or v.readonly))]

    def pick_type(self, allow_mat=True, allow_bool=True, allow_struct=False):
        r = self.r.random()
        if allow_struct and self.structs and r < 0.08:
            return self.r.choice(list(self.structs))
        if allow_mat and r < 0.18:
            return self.r.choice(list(MATS))
        pool = SCALAR_VEC if allow_bool else NUMERIC
        # favour float types
        if self.chance(0.45):
            return self.r.choice(GEN_F)
        return self.r.choice(pool)

    @staticmethod
    def wrap(e, need):
        s, p = e
        return "(" + s + ")" if p < need else s

    def paren(self, e):
        s, p = e
        if p < P_PRIMARY and self.chance(0.1):
            return ("(" + s + ")", P_PRIMARY)
        return e

    # ----------------------------------------------------------------- literals
    def lit(self, base):
        r = self.r
        if base == "float":
            c = r.random()
            if c < 0.5:
                return ("%.1f" % r.choice([0, 0.5, 1, 2, 3, 0.25, 10, 100]), P_PRIMARY)
            if c < 0.7:
                return ("%.3f" % r.uniform(0, 4), P_PRIMARY)
            if c < 0.8:
                return (r.choice(["1e2", "2.5e-1", ".5", "3.", "1.0E1", "0.0"]), P_PRIMARY)
            return (str(r.randint(0, 9)) + ".0", P_PRIMARY)
        if base == "int":
            c = r.random()
            if c < 0.8:
                return (str(r.randint(0, 9)), P_PRIMARY)
            if c < 0.9:
                return (hex(r.randint(0, 255)), P_PRIMARY)
            return (str(r.randint(10, 1000)), P_PRIMARY)
        if base == "uint":
            return (str(r.randint(0, 20)) + r.choice(["u", "U"]), P_PRIMARY)
        return (r.choice(["true", "false"]), P_PRIMARY)

    # ----------------------------------------------------------------- expressions
    def expr(self, t, d=0, const=False):
        """An expression of type t as (text, precedence)."""
        if t in self.structs:
            return self.struct_expr(t, d, const)
        if d > 3 or (d > 1 and self.chance(0.4)):
            return self.leaf(t, const)
        choices = [self.leaf, self.ctor, self.arith, self.unary, self.call_builtin, self.ternary,
                   self.compare, self.logical, self.bitwise, self.swizzle_of, self.index_of,
                   self.user_call, self.assign_expr, self.comma, self.incdec, self.field_of]
        weights = [5, 3, 5, 1, 4, 1, 2, 2, 1, 2, 2, 1, 1, 0.3, 0.5, 1]
        for _ in range(6):
            f = self.r.choices(choices, weights)[0]
            e = f(t, d + 1, const) if f != self.leaf else f(t, const)
            if e is not None:
                return self.paren(e)
        return self.leaf(t, const)

    def leaf(self, t, const=False):
        if t in MATS:
            if self.chance(0.5):
                vs = [v for v in self.vars_of(t) if v.const or not const]
                if vs:
                    return (self.r.choice(vs).name, P_PRIMARY)
            return self.ctor(t, 4, const)
        if t in self.structs:
            return self.struct_expr(t, 3, const)
        vs = [v for v in self.vars_of(t) if v.const or not const]
        if vs and self.chance(0.7):
            return (self.r.choice(vs).name, P_PRIMARY)
        base, n = INFO[t]
        if n == 1:
            return self.lit(base)
        return self.ctor(t, 4, const)

    def ctor(self, t, d, const=False):
        if t in self.structs:
            return self.struct_expr(t, d, const)
        if t in MATS:
            c, r = MATS[t]
            k = self.r.random()
            if k < 0.3:
                return ("%s(%s)" % (t, self.wrap(self.expr("float", d, const), P_ASSIGN)), P_PRIMARY)
            if k < 0.5:
                other = self.r.choice(list(MATS))
                return ("%s(%s)" % (t, self.wrap(self.expr(other, d, const), P_ASSIGN)), P_PRIMARY)
            cols = [self.wrap(self.expr(FLOAT_VEC[r], d + 1, const), P_ASSIGN) for _ in range(c)]
            return ("%s(%s)" % (t, ", ".join(cols)), P_PRIMARY)
        base, n = INFO[t]
        if n == 1:
            src = self.r.choice(["float", "int", "uint", "bool", base, base])
            if self.chance(0.2):
                src = self.r.choice(VECS[src][2:] if False else list(VECS[src].values())[1:])
            return ("%s(%s)" % (t, self.wrap(self.expr(src, d, const), P_ASSIGN)), P_PRIMARY)
        if self.chance(0.25):
            src = self.r.choice([base, base, "float", "int", "uint", "bool"])
            return ("%s(%s)" % (t, self.wrap(self.expr(src, d, const), P_ASSIGN)), P_PRIMARY)
        if self.chance(0.1):
            src = VECS[self.r.choice(["float", "int", "uint", "bool"])][n]
            return ("%s(%s)" % (t, self.wrap(self.expr(src, d, const), P_ASSIGN)), P_PRIMARY)
        # split n components into parts
        parts, left = [], n
        while left:
            k = self.r.randint(1, left)
            if k == n and n > 1:
                k = 1
            parts.append(k)
            left -= k
        args = []
        for k in parts:
            b = base if self.chance(0.7) else self.r.choice(["float", "int", "uint", "bool"])
            args.append(self.wrap(self.expr(VECS[b][k], d + 1, const), P_ASSIGN))
        return ("%s(%s)" % (t, ", ".join(args)), P_PRIMARY)

    def struct_expr(self, t, d, const=False):
        vs = [v for v in self.vars_of(t) if v.const or not const]
        if vs and self.chance(0.5):
            return (self.r.choice(vs).name, P_PRIMARY)
        args = []
        for ft, fn, fa in self.structs[t]:
            if fa:
                args.append(self.array_ctor(ft, fa, d + 1, const))
            else:
                args.append(self.wrap(self.expr(ft, d + 1, const), P_ASSIGN))
        return ("%s(%s)" % (t, ", ".join(args)), P_PRIMARY)

    def array_ctor(self, t, n, d, const=False):
        items = [self.wrap(self.expr(t, d + 1, const), P_ASSIGN) for _ in range(n)]
        return "%s[%s](%s)" % (t, self.r.choice([str(n), ""]), ", ".join(items))

    def binop(self, op, a, b, res=None):
        p = BIN_PREC[op]
        return ("%s %s %s" % (self.wrap(a, p), op, self.wrap(b, p + 1)), p)

    def arith(self, t, d, const=False):
        if t in MATS:
            c, r = MATS[t]
            k = self.r.random()
            if k < 0.4:
                op = self.r.choice(["+", "-", "/", "*"])
                a, b = self.expr(t, d, const), self.expr(t, d, const)
                if op == "*":
                    if c != r:
                        op = "+"
                    return self.binop(op, a, b)
                return self.binop(op, a, b)
            if k < 0.7:
                op = self.r.choice(["+", "-", "*", "/"])
                a, b = self.expr(t, d, const), self.expr("float", d, const)
                return self.binop(op, a, b) if self.chance(0.5) else self.binop(op, b, a)
            # linear algebra: (k x r) * (c x k)
            kk = self.r.choice([2, 3, 4])
            ta = [n for n, cr in MATS.items() if cr == (kk, r)][0]
            tb = [n for n, cr in MATS.items() if cr == (c, kk)][0]
            return self.binop("*", self.expr(ta, d, const), self.expr(tb, d, const))
        base, n = INFO[t]
        if base == "bool":
            return None
        ops = ["+", "-", "*", "/"] + (["%"] if base != "float" else [])
        op = self.r.choice(ops)
        k = self.r.random()
        if n > 1 and base == "float" and op == "*" and k < 0.3:
            # matrix * vector or vector * matrix
            m = self.r.choice([m for m, (c, r) in MATS.items() if r == n] if self.chance(0.5)
                              else [m for m, (c, r) in MATS.items() if c == n])
            c, r = MATS[m]
            if r == n:
                return self.binop("*", self.expr(m, d, const), self.expr(FLOAT_VEC[c], d, const))
            return self.binop("*", self.expr(FLOAT_VEC[r], d, const), self.expr(m, d, const))
        if n > 1 and k < 0.5:
            a, b = self.expr(t, d, const), self.expr(base, d, const)
            if self.chance(0.5):
                a, b = b, a
            return self.binop(op, a, b)
        return self.binop(op, self.expr(t, d, const), self.expr(t, d, const))

    def unary(self, t, d, const=False):
        if t in MATS:
            op = self.r.choice(["-", "+"])
        else:
            base, n = INFO[t]
            if base == "bool":
                if n > 1:
                    return None
                op = "!"
            elif base == "float":
                op = self.r.choice(["-", "+"])
            else:
                op = self.r.choice(["-", "+", "~"])
        s = self.wrap(self.expr(t, d, const), P_UNARY)
        if s[0] in "+-!~":
            s = "(" + s + ")"
        return (op + s, P_UNARY)

    def incdec(self, t, d, const=False):
        if const or t in MATS or INFO[t][0] == "bool":
            return None if t not in MATS or const else None
        vs = self.vars_of(t, writable=True)
        if not vs:
            return None
        op = self.r.choice(["++", "--"])
        v = self.r.choice(vs).name
        return ((op + v, P_UNARY) if self.chance(0.5) else (v + op, P_POSTFIX))

    def compare(self, t, d, const=False):
        if t != "bool":
            return None
        if self.chance(0.5):
            st = self.r.choice(["float", "int", "uint"])
            op = self.r.choice(["<", ">", "<=", ">="])
        else:
            st = self.pick_type(allow_struct=True)
            op = self.r.choice(["==", "!="])
        return self.binop(op, self.expr(st, d, const), self.expr(st, d, const))

    def logical(self, t, d, const=False):
        if t != "bool":
            return None
        op = self.r.choice(["&&", "||", "^^"])
        return self.binop(op, self.expr("bool", d, const), self.expr("bool", d, const))

    def bitwise(self, t, d, const=False):
        if t in MATS or INFO[t][0] not in ("int", "uint"):
            return None
        base, n = INFO[t]
        op = self.r.choice(["&", "|", "^", "<<", ">>"])
        if op in ("<<", ">>"):
            ob = self.r.choice(["int", "uint"])
            rt = VECS[ob][n] if self.chance(0.5) else ob
            if op == "<<" or op == ">>":
                # keep constant shift amounts small and non-negative
                rhs = (str(self.r.randint(0, 7)) + ("u" if ob == "uint" else ""), P_PRIMARY) \
                    if rt == ob and self.chance(0.6) else self.expr(rt, d, const)
            return self.binop(op, self.expr(t, d, const), rhs)
        if n > 1 and self.chance(0.3):
            a, b = self.expr(t, d, const), self.expr(base, d, const)
            if self.chance(0.5):
                a, b = b, a
            return self.binop(op, a, b)
        return self.binop(op, self.expr(t, d, const), self.expr(t, d, const))

    def ternary(self, t, d, const=False):
        c = self.wrap(self.expr("bool", d, const), P_OR)
        a = self.expr(t, d, const)
        a = a[0] if a[1] >= P_COMMA else "(" + a[0] + ")"
        b = self.wrap(self.expr(t, d, const), P_ASSIGN)
        return ("%s ? %s : %s" % (c, a, b), P_COND)

    def comma(self, t, d, const=False):
        if const:
            return None
        st = self.pick_type()
        a = self.wrap(self.expr(st, d + 1), P_COMMA)
        b = self.wrap(self.expr(t, d + 1), P_ASSIGN)
        return ("%s, %s" % (a, b), P_COMMA)

    def assign_expr(self, t, d, const=False):
        if const:
            return None
        vs = self.vars_of(t, writable=True)
        if not vs:
            return None
        v = self.r.choice(vs).name
        op = "="
        if t not in MATS and INFO[t][0] != "bool" and self.chance(0.4):
            op = self.r.choice(["+=", "-=", "*=", "/="])
        return ("%s %s %s" % (v, op, self.wrap(self.expr(t, d), P_ASSIGN)), P_ASSIGN)

    def swizzle_of(self, t, d, const=False):
        if t in MATS:
            return None
        base, n = INFO[t]
        src_n = self.r.choice([2, 3, 4])
        src = VECS[base][src_n]
        sets = self.r.choice(["xyzw", "rgba", "stpq"])
        comps = "".join(self.r.choice(sets[:src_n]) for _ in range(n))
        e = self.expr(src, d, const)
        return ("%s.%s" % (self.wrap(e, P_POSTFIX), comps), P_POSTFIX)

    def index_of(self, t, d, const=False):
        # vector component, matrix column, or array element
        if t in MATS:
            arrs = self.array_vars(t)
            if arrs and not const:
                a = self.r.choice(arrs)
                return ("%s[%s]" % (a.name, self.index_expr(a.array, d)), P_POSTFIX)
            return None
        base, n = INFO[t]
        k = self.r.random()
        arrs = [a for a in self.array_vars(t) if a.const or not const]
        if arrs and k < 0.4:
            a = self.r.choice(arrs)
            return ("%s[%s]" % (a.name, self.index_expr(a.array, d, const or a.const_index)), P_POSTFIX)
        if n == 1:
            if base == "float" and k < 0.7:
                m = self.r.choice(list(MATS))
                c, r = MATS[m]
                return ("%s[%s][%s]" % (self.wrap(self.expr(m, d, const), P_POSTFIX),
                                        self.index_expr(c, d, const), self.index_expr(r, d, const)),
                        P_POSTFIX)
            vn = self.r.choice([2, 3, 4])
            return ("%s[%s]" % (self.wrap(self.expr(VECS[base][vn], d, const), P_POSTFIX),
                                self.index_expr(vn, d, const)), P_POSTFIX)
        if base == "float":
            m = self.r.choice([m for m, (c, r) in MATS.items() if r == n])
            return ("%s[%s]" % (self.wrap(self.expr(m, d, const), P_POSTFIX),
                                self.index_expr(MATS[m][0], d, const)), P_POSTFIX)
        return None

    def index_expr(self, size, d, const=False):
        k = self.r.random()
        if k < 0.5 or const:
            return str(self.r.randint(0, size - 1))
        ints = self.vars_of("int", nonconst=True)
        if ints and k < 0.8:
            return self.r.choice(ints).name
        return "clamp(%s, 0, %d)" % (self.wrap(self.expr("int", d + 1), P_ASSIGN), size - 1)

    def field_of(self, t, d, const=False):
        cands = [(s, fn, fa) for s, fields in self.structs.items() for ft, fn, fa in fields if ft == t]
        if not cands:
            return None
        s, fn, fa = self.r.choice(cands)
        e = "%s.%s" % (self.wrap(self.struct_expr(s, d, const), P_POSTFIX), fn)
        if fa:
            e += "[%s]" % self.index_expr(fa, d, const)
        return (e, P_POSTFIX)

    def user_call(self, t, d, const=False):
        if const:
            return None
        fs = [f for f in self.funcs if f.ret == t]
        if not fs:
            return None
        f = self.r.choice(fs)
        args = []
        for q, pt, pn in f.params:
            if q in ("out", "inout"):
                vs = self.vars_of(pt, writable=True)
                if not vs:
                    return None
                args.append(self.r.choice(vs).name)
            else:
                args.append(self.wrap(self.expr(pt, d), P_ASSIGN))
        return ("%s(%s)" % (f.name, ", ".join(args)), P_POSTFIX)

    # built-in functions: list of (name, [arg kinds], result kind); 'G' = genType slot
    def call_builtin(self, t, d, const=False):
        r = self.r
        a = lambda tt: self.wrap(self.expr(tt, d, const), P_ASSIGN)
        call = lambda name, *args: ("%s(%s)" % (name, ", ".join(args)), P_POSTFIX)
        if t in MATS:
            c, rr = MATS[t]
            k = r.random()
            if k < 0.3:
                return call("matrixCompMult", a(t), a(t))
            if k < 0.55:
                tt = [m for m, cr in MATS.items() if cr == (rr, c)][0]
                return call("transpose", a(tt))
            if k < 0.75 and c == rr:
                return call("inverse", a(t))
            return call("outerProduct", a(FLOAT_VEC[rr]), a(FLOAT_VEC[c]))
        base, n = INFO[t]
        if base == "float":
            opts = ["f1", "f1", "f2", "f3", "mix", "step", "clamp", "geom"]
            if n == 1:
                opts += ["scalar"]
            o = r.choice(opts)
            if o == "f1":
                name = r.choice(["radians", "degrees", "sin", "cos", "tan", "asin", "acos", "atan",
                                 "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "exp", "log",
                                 "exp2", "log2", "sqrt", "inversesqrt", "abs", "sign", "floor",
                                 "trunc", "round", "roundEven", "ceil", "fract", "normalize"]
                                + (["dFdx", "dFdy", "fwidth"] if self.stage == "frag" and not const else []))
                return call(name, a(t))
            if o == "f2":
                name = r.choice(["atan", "pow", "mod", "min", "max", "step", "reflect"])
                second = t
                if name in ("mod", "min", "max") and self.chance(0.4):
                    second = "float"
                return call(name, a(t), a(second))
            if o == "f3":
                name = r.choice(["faceforward", "smoothstep", "clamp", "refract"])
                if name == "refract":
                    return call(name, a(t), a(t), a("float"))
                if name == "smoothstep" and self.chance(0.4):
                    return call(name, a("float"), a("float"), a(t))
                return call(name, a(t), a(t), a(t))
            if o == "mix":
                third = r.choice([t, "float", BOOL_VEC[n]])
                return call("mix", a(t), a(t), a(third))
            if o == "step":
                return call("step", a("float"), a(t))
            if o == "clamp":
                return call("clamp", a(t), a("float"), a("float"))
            if o == "geom":
                if n == 3 and self.chance(0.4):
                    return call("cross", a("vec3"), a("vec3"))
                if n == 1:
                    vt = r.choice(GEN_F)
                    name = r.choice(["length", "distance", "dot", "determinant"])
                    if name == "length":
                        return call(name, a(vt))
                    if name == "determinant":
                        return call(name, a(r.choice(["mat2", "mat3", "mat4"])))
                    return call(name, a(vt), a(vt))
                k = r.random()
                if k < 0.3:
                    return call(r.choice(["intBitsToFloat"]), a(INT_VEC[n]))
                if k < 0.5:
                    return call("uintBitsToFloat", a(UINT_VEC[n]))
                if n == 2 and k < 0.7:
                    return call(r.choice(["unpackSnorm2x16", "unpackUnorm2x16", "unpackHalf2x16"]),
                                a("uint"))
                if n == 4 and not const and self.samplers and k < 0.95:
                    return self.texture_call(t, d)
                return call("normalize", a(t))
            # scalar
            return call(r.choice(["length", "dot"]), a("vec3"), *([a("vec3")] if self.chance(0.5) else []))[0:1] + (P_POSTFIX,) \
                if False else call("length", a(r.choice(GEN_F)))
        if base in ("int", "uint"):
            k = r.random()
            if k < 0.25:
                name = r.choice(["min", "max"])
                return call(name, a(t), a(t if self.chance(0.6) else base))
            if k < 0.4:
                return call("clamp", a(t), *(2 * [a(base)] if self.chance(0.5) else [a(t), a(t)]))
            if k < 0.5 and base == "int":
                return call(r.choice(["abs", "sign"]), a(t))
            if k < 0.65:
                return call("floatBitsToInt" if base == "int" else "floatBitsToUint", a(FLOAT_VEC[n]))
            if k < 0.75 and base == "uint" and n == 1:
                return call(r.choice(["packSnorm2x16", "packUnorm2x16", "packHalf2x16"]), a("vec2"))
            if k < 0.85 and self.samplers and not const and base == "int" and n in (2, 3):
                cands = [s for s in self.samplers if SAMPLERS[s.type][2] == t]
                if cands:
                    s = r.choice(cands)
                    return call("textureSize", s.name, a("int"))
            if k < 0.95 and self.samplers and not const and n == 4:
                return self.texture_call(t, d)
            return call("min", a(t), a(t))
        # bool
        if n == 1:
            k = r.random()
            if k < 0.6:
                return call(r.choice(["any", "all"]), a(r.choice(GEN_B[1:])))
            return call(r.choice(["isnan", "isinf"]), a("float"))
        k = r.random()
        if k < 0.5:
            src = r.choice([FLOAT_VEC[n], INT_VEC[n], UINT_VEC[n]])
            name = r.choice(["lessThan", "lessThanEqual", "greaterThan", "greaterThanEqual",
                             "equal", "notEqual"])
            return call(name, a(src), a(src))
        if k < 0.7:
            return call(r.choice(["equal", "notEqual"]), a(t), a(t))
        if k < 0.85:
            return call("not", a(t))
        return call(r.choice(["isnan", "isinf"]), a(FLOAT_VEC[n]))

    def texture_call(self, t, d):
        cands = [s for s in self.samplers if SAMPLERS[s.type][3] == t]
        if not cands:
            return None
        s = self.r.choice(cands)
        coord, fetch, size, res = SAMPLERS[s.type]
        a = lambda tt: self.wrap(self.expr(tt, d), P_ASSIGN)
        k = self.r.random()
        if k < 0.3 and fetch:
            return ("texelFetch(%s, %s, %s)" % (s.name, a(fetch), a("int")), P_POSTFIX)
        if k < 0.5:
            return ("textureLod(%s, %s, %s)" % (s.name, a(coord), a("float")), P_POSTFIX)
        if k < 0.6 and self.stage == "frag":
            return ("texture(%s, %s, %s)" % (s.name, a(coord), a("float")), P_POSTFIX)
        if k < 0.7 and s.type == "sampler2D":
            return ("textureProj(%s, %s)" % (s.name, a("vec3")), P_POSTFIX)
        if k < 0.8 and s.type in ("sampler2D", "sampler3D"):
            return ("textureOffset(%s, %s, %s(1))" % (s.name, a(coord), "ivec" + coord[-1]), P_POSTFIX)
        return ("texture(%s, %s)" % (s.name, a(coord)), P_POSTFIX)

    # ----------------------------------------------------------------- const exprs
    def const_expr(self, t):
        return self.expr(t, 2, const=True)

    # ----------------------------------------------------------------- statements
    def stmt_list(self, n, d, out):
        for _ in range(n):
            self.stmt(d, out)

    def ind(self, d):
        return "    " * d

    def block(self, d, out, n=None, new_scope=True):
        if new_scope:
            self.scopes.append({})
        self.stmt_list(n if n is not None else self.r.randint(1, 3), d, out)
        if new_scope:
            self.scopes.pop()

    def decl_stmt(self, d, out):
        t = self.pick_type(allow_struct=True)
        nm = self.name()
        prec = (self.r.choice(PREC) + " ") if (INFO.get(t, ("float",))[0] != "bool" and t not in self.structs
                                               and self.chance(0.15)) else ""
        if self.chance(0.12):
            n = self.r.randint(1, 4)
            if self.chance(0.5):
                out.append("%s%s%s %s[%d] = %s;" % (self.ind(d), prec, t, nm, n, self.array_ctor(t, n, 1)))
            elif self.chance(0.5):
                out.append("%s%s%s[%d] %s;" % (self.ind(d), prec, t, n, nm))
            else:
                out.append("%s%s%s %s[%d];" % (self.ind(d), prec, t, nm, n))
            self.declare(Var(nm, t, array=n))
            return
        if self.chance(0.15) and t not in self.structs:
            e = self.const_expr(t)
            out.append("%sconst %s%s %s = %s;" % (self.ind(d), prec, t, nm, self.wrap(e, P_ASSIGN)))
            self.declare(Var(nm, t, const=True))
            return
        if self.chance(0.2):
            nm2 = self.name()
            out.append("%s%s%s %s = %s, %s;" % (self.ind(d), prec, t, nm, self.wrap(self.expr(t, 1), P_ASSIGN), nm2))
            self.declare(Var(nm, t))
            self.declare(Var(nm2, t))
            return
        out.append("%s%s%s %s = %s;" % (self.ind(d), prec, t, nm, self.wrap(self.expr(t, 1), P_ASSIGN)))
        self.declare(Var(nm, t))

    def lvalue(self, t):
        """A writable l-value of type t, or None."""
        k = self.r.random()
        if t not in MATS and t not in self.structs and k < 0.25:
            base, n = INFO[t]
            srcs = [v for m in (2, 3, 4) for v in self.vars_of(VECS[base][m], writable=True)]
            if srcs:
                v = self.r.choice(srcs)
                m = INFO[v.type][1]
                sets = self.r.choice(["xyzw", "rgba", "stpq"])[:m]
                if n <= m:
                    comps = "".join(self.r.sample(sets, n))
                    return "%s.%s" % (v.name, comps)
        if k < 0.4:
            arrs = self.array_vars(t, writable=True)
            if arrs:
                a = self.r.choice(arrs)
                return "%s[%s]" % (a.name, self.index_expr(a.array, 2, a.const_index))
        vs = self.vars_of(t, writable=True)
        if vs:
            return self.r.choice(vs).name
        return None

    def assign_stmt(self, d, out):
        for _ in range(4):
            t = self.pick_type(allow_struct=True)
            lv = self.lvalue(t)
            if lv:
                break
        else:
            return self.decl_stmt(d, out)
        op = "="
        if t not in self.structs and (t in MATS or INFO[t][0] != "bool") and self.chance(0.35):
            ops = ["+=", "-=", "*=", "/="]
            if t not in MATS and INFO[t][0] in ("int", "uint"):
                ops += ["%=", "&=", "|=", "^=", "<<=", ">>="]
            op = self.r.choice(ops)
            if op in ("<<=", ">>="):
                out.append("%s%s %s %s;" % (self.ind(d), lv, op, self.r.randint(0, 5)))
                return
            if t not in MATS and INFO[t][1] > 1 and self.chance(0.3):
                out.append("%s%s %s %s;" % (self.ind(d), lv, op, self.wrap(self.expr(INFO[t][0], 1), P_ASSIGN)))
                return
            if t in MATS and op == "*=" and MATS[t][0] != MATS[t][1]:
                op = "+="
        out.append("%s%s %s %s;" % (self.ind(d), lv, op, self.wrap(self.expr(t, 1), P_ASSIGN)))

    def stmt(self, d, out):
        if d > 5:
            return self.assign_stmt(d, out)
        self.maybe_mutate_stmt(d, out)
        k = self.r.random()
        if k < 0.25:
            return self.decl_stmt(d, out)
        if k < 0.48:
            return self.assign_stmt(d, out)
        if k < 0.55:
            t = self.pick_type()
            out.append("%s%s;" % (self.ind(d), self.expr(t, 1)[0]))
            return
        if k < 0.65:
            out.append("%sif (%s) {" % (self.ind(d), self.expr("bool", 1)[0]))
            self.block(d + 1, out)
            if self.chance(0.5):
                if self.chance(0.3):
                    out.append("%s} else if (%s) {" % (self.ind(d), self.expr("bool", 1)[0]))
                    self.block(d + 1, out)
                out.append("%s} else {" % self.ind(d))
                self.block(d + 1, out)
            out.append("%s}" % self.ind(d))
            return
        if k < 0.72:
            i = self.name("i")
            it = self.r.choice(["int", "int", "uint"])
            suf = "u" if it == "uint" else ""
            self.scopes.append({})
            self.declare(Var(i, it))
            step = self.r.choice(["%s++" % i, "++%s" % i, "%s += 1%s" % (i, suf), "%s = %s + 1%s" % (i, i, suf)])
            out.append("%sfor (%s %s = 0%s; %s < %d%s; %s) {" % (self.ind(d), it, i, suf, i,
                                                              self.r.randint(1, 8), suf, step))
            self.loop_depth += 1
            self.block(d + 1, out, new_scope=False)
            if self.chance(0.3):
                out.append("%sif (%s) %s;" % (self.ind(d + 1), self.expr("bool", 2)[0],
                                               self.r.choice(["break", "continue"])))
            self.loop_depth -= 1
            self.scopes.pop()
            out.append("%s}" % self.ind(d))
            return
        if k < 0.76:
            self.loop_depth += 1
            if self.chance(0.5):
                out.append("%swhile (%s) {" % (self.ind(d), self.expr("bool", 1)[0]))
                self.block(d + 1, out)
                out.append("%s    break;" % self.ind(d))
                out.append("%s}" % self.ind(d))
            else:
                out.append("%sdo {" % self.ind(d))
                self.block(d + 1, out)
                if self.chance(0.4):
                    out.append("%s    if (%s) continue;" % (self.ind(d), self.expr("bool", 2)[0]))
                out.append("%s} while (%s);" % (self.ind(d), self.expr("bool", 1)[0]))
            self.loop_depth -= 1
            return
        if k < 0.82:
            return self.switch_stmt(d, out)
        if k < 0.86:
            out.append("%s{" % self.ind(d))
            self.block(d + 1, out)
            out.append("%s}" % self.ind(d))
            return
        if k < 0.88 and self.stage == "frag":
            out.append("%sif (%s) discard;" % (self.ind(d), self.expr("bool", 1)[0]))
            return
        if k < 0.90 and (self.loop_depth or self.switch_depth) and self.chance(0.5):
            out.append("%sif (%s) break;" % (self.ind(d), self.expr("bool", 1)[0]))
            return
        if k < 0.92:
            if self.cur_ret == "void":
                out.append("%sif (%s) return;" % (self.ind(d), self.expr("bool", 1)[0]))
            else:
                out.append("%sif (%s) return %s;" % (self.ind(d), self.expr("bool", 1)[0],
                                                    self.wrap(self.expr(self.cur_ret, 2), P_COMMA)))
            return
        return self.assign_stmt(d, out)

    def switch_stmt(self, d, out, bad=None):
        st = self.r.choice(["int", "int", "uint"])
        suf = "u" if st == "uint" else ""
        sel = self.expr(st, 1)[0]
        if bad == "float":
            sel = "float(%s)" % sel
        out.append("%sswitch (%s) {" % (self.ind(d), sel))
        if bad == "stmt_first":
            out.append("%s%s;" % (self.ind(d + 1), self.expr("int", 2)[0]))
        labels = self.r.sample(range(0, 10), self.r.randint(1, 4))
        if bad == "dup":
            labels.append(labels[0])
        self.switch_depth += 1
        for j, lab in enumerate(labels):
            ls = "%d%s" % (lab, suf)
            if bad == "type":
                ls = "%d%s" % (lab, "" if suf else "u")
                bad = None
            out.append("%scase %s:" % (self.ind(d + 1), ls))
            if self.chance(0.85) or j == len(labels) - 1:
                out.append("%s{" % self.ind(d + 2))
                self.block(d + 3, out, self.r.randint(1, 2))
                out.append("%s}" % self.ind(d + 2))
                if self.chance(0.8):
                    out.append("%sbreak;" % self.ind(d + 2))
        if self.chance(0.6):
            out.append("%sdefault:" % self.ind(d + 1))
            self.block(d + 2, out, 1)
            if bad == "empty_last":
                out.pop()
                out.append("%sbreak;" % self.ind(d + 2))
        self.switch_depth -= 1
        out.append("%s}" % self.ind(d))

    # ----------------------------------------------------------------- mutations in statements
    def maybe_mutate_stmt(self, d, out):
        if not self.mut or self.chance(0.75):
            return
        r = self.r
        I = self.ind(d)
        kind = self.mut[0]
        if kind in ("discard_vertex",) and self.stage != "vert":
            self.mut.pop(0)
            return
        local = [v for v in self.all_vars()]
        if kind == "type_mismatch" and self.take(kind):
            t = self.pick_type()
            u = self.pick_type()
            while u == t or (t in MATS and u in MATS):
                u = self.pick_type()
            out.append("%s%s %s = %s;" % (I, t, self.name(), self.wrap(self.expr(u, 1), P_ASSIGN)))
        elif kind == "undeclared" and self.take(kind):
            out.append("%sfloat %s = %s + 1.0;" % (I, self.name(), r.choice(["undeclared_x", "v999", "gl_Foo", "fooBar"])))
        elif kind == "builtin_arity" and self.take(kind):
            out.append(I + r.choice(["float %s = dot(%s);" % (self.name(), self.expr("vec3", 2)[0]),
                                     "float %s = clamp(%s, 1.0);" % (self.name(), self.expr("float", 2)[0]),
                                     "vec3 %s = cross(vec3(1.0));" % self.name(),
                                     "float %s = sin();" % self.name(),
                                     "float %s = pow(%s, 1.0, 2.0);" % (self.name(), self.expr("float", 2)[0]),
                                     "float %s = mix(1.0, 2.0);" % self.name()]))
        elif kind == "builtin_argtype" and self.take(kind):
            out.append(I + r.choice(["float %s = length(%s);" % (self.name(), self.expr("int", 2)[0]),
                                     "float %s = sin(%s);" % (self.name(), self.expr("ivec2", 2)[0]),
                                     "vec3 %s = cross(vec2(1.0), vec2(2.0));" % self.name(),
                                     "float %s = dot(vec2(1.0), vec3(1.0));" % self.name(),
                                     "int %s = abs(%s);" % (self.name(), self.expr("uint", 2)[0]),
                                     "bool %s = any(%s);" % (self.name(), self.expr("vec2", 2)[0]),
                                     "mat3 %s = inverse(mat2x3(1.0));" % self.name(),
                                     "float %s = mod(%s, 2);" % (self.name(), self.expr("float", 2)[0])]))
        elif kind == "ctor_arity" and self.take(kind):
            out.append(I + r.choice(["vec3 %s = vec3(1.0, 2.0);" % self.name(),
                                     "vec2 %s = vec2(1.0, 2.0, 3.0);" % self.name(),
                                     "mat2 %s = mat2(1.0, 2.0, 3.0);" % self.name(),
                                     "float %s = float();" % self.name(),
                                     "ivec4 %s = ivec4(ivec2(1), 2);" % self.name(),
                                     "vec4 %s = vec4(vec3(1.0), vec2(1.0), 1.0);" % self.name(),
                                     "mat2 %s = mat2(vec3(1.0), 1.0);" % self.name()]))
        elif kind == "lvalue" and self.take(kind):
            fv = self.vars_of("float", writable=True)
            vv = self.vars_of("vec3", writable=True) + self.vars_of("vec4", writable=True)
            opts = ["(%s + 1.0) = 2.0;" % (fv[0].name if fv else "1.0"), "1 = 2;",
                    "vec3(1.0) = vec3(2.0);", "sin(1.0) = 0.5;"]
            if vv:
                opts.append("%s.xx = vec2(1.0);" % vv[0].name)
                opts.append("%s.xyx += vec3(1.0);" % vv[0].name)
            if fv:
                opts.append("%s++ = 1.0;" % fv[0].name)
                opts.append("(%s, %s) = 1.0;" % (fv[0].name, fv[-1].name))
            out.append(I + r.choice(opts))
        elif kind == "const_write" and self.take(kind):
            cs = [v for v in local if v.const and v.array is None and v.type in INFO and INFO[v.type][0] != "bool"]
            if cs:
                v = r.choice(cs)
                out.append("%s%s %s %s;" % (I, v.name, r.choice(["=", "+="]), self.expr(v.type, 2)[0]))
            else:
                nm = self.name()
                out.append("%sconst float %s = 1.0;" % (I, nm))
                out.append("%s%s%s;" % (I, r.choice(["++", "--"]), nm))
        elif kind == "readonly_write" and self.take(kind):
            ro = [v for v in local if v.readonly and not v.type.startswith(("sampler", "isampler", "usampler"))
                  and v.array is None and v.type in INFO]
            if ro and self.chance(0.7):
                v = r.choice(ro)
                out.append("%s%s = %s;" % (I, v.name, self.expr(v.type, 2)[0]))
            else:
                out.append(I + (r.choice(["gl_FragCoord = vec4(1.0);", "gl_FrontFacing = true;",
                                          "gl_PointCoord = vec2(0.0);"]) if self.stage == "frag"
                                else r.choice(["gl_VertexID = 1;", "gl_InstanceID = 2;"])))
        elif kind == "bad_swizzle" and self.take(kind):
            out.append(I + r.choice(["float %s = vec2(1.0).z;" % self.name(),
                                     "vec2 %s = vec4(1.0).xg;" % self.name(),
                                     "vec4 %s = vec4(1.0).xyzwx;" % self.name(),
                                     "vec3 %s = vec3(1.0).stq;" % self.name(),
                                     "float %s = vec3(1.0).w;" % self.name(),
                                     "vec2 %s = vec4(1.0).xa;" % self.name(),
                                     "vec2 %s = vec4(1.0).rs;" % self.name()]))
        elif kind == "scalar_swizzle" and self.take(kind):
            out.append(I + r.choice(["float %s = 1.0.x;" % self.name(),
                                     "vec2 %s = %s.xx;" % (self.name(), self.wrap(self.expr("float", 2), P_POSTFIX)),
                                     "int %s = %s.r;" % (self.name(), self.wrap(self.expr("int", 2), P_POSTFIX))]))
        elif kind == "index_oob" and self.take(kind):
            arrs = [v for v in local if v.array is not None]
            opts = ["float %s = vec4(1.0)[4];" % self.name(), "vec2 %s = mat2(1.0)[2];" % self.name(),
                    "float %s = vec3(1.0)[-1];" % self.name(),
                    "float %s = float[2](1.0, 2.0)[2];" % self.name()]
            if arrs:
                a = r.choice(arrs)
                opts.append("%s[%d];" % (a.name, a.array + r.randint(0, 2)))
            out.append(I + r.choice(opts))
        elif kind == "redeclare" and self.take(kind):
            same = list(self.scopes[-1].values())
            if same and len(self.scopes) > 1:
                v = r.choice(same)
                out.append("%sfloat %s = 1.0;" % (I, v.name))
            else:
                nm = self.name()
                out.append("%sint %s = 1;" % (I, nm))
                out.append("%sfloat %s = 2.0;" % (I, nm))
        elif kind == "break_outside" and not self.loop_depth and not self.switch_depth and self.take(kind):
            out.append(I + r.choice(["break;", "continue;", "if (true) break;", "if (false) continue;"]))
        elif kind == "return_mismatch" and self.take(kind):
            if self.cur_ret == "void":
                out.append("%sreturn %s;" % (I, self.expr("float", 2)[0]))
            else:
                out.append("%s%s" % (I, r.choice(["return;", "return %s;" % self.expr(
                    "bool" if self.cur_ret != "bool" else "float", 2)[0]])))
        elif kind == "reserved_name" and self.take(kind):
            nm = r.choice(["webgl_x", "_webgl_y", "a__b", "gl_z", "__x", "webgl_", "x__"]) + str(self.counter)
            out.append("%sfloat %s = 1.0;" % (I, nm))
        elif kind == "discard_vertex" and self.take(kind):
            out.append(I + "discard;")
        elif kind == "nonconst_size" and self.take(kind):
            ints = self.vars_of("int", nonconst=True)
            if ints:
                out.append("%sfloat %s[%s];" % (I, self.name(), ints[0].name))
            else:
                fs = self.vars_of("float", nonconst=True)
                out.append("%sconst float %s = %s;" % (I, self.name(), fs[0].name if fs else "sin(gl_FragCoord.x)"
                                                     if self.stage == "frag" else "float(gl_VertexID)"))
        elif kind == "switch_error" and self.take(kind):
            self.switch_stmt(d, out, bad=r.choice(["float", "dup", "type", "stmt_first", "empty_last"]))
        elif kind == "bad_condition" and self.take(kind):
            e = self.expr(r.choice(["int", "float", "bvec2", "uint"]), 2)[0]
            out.append(I + r.choice(["if (%s) {}" % e, "while (%s) { break; }" % e,
                                     "for (;%s;) { break; }" % e, "do {} while (%s);" % e]))
        elif kind == "call_error" and self.take(kind):
            fs = [f for f in self.funcs if f.params]
            if fs and self.chance(0.6):
                f = r.choice(fs)
                args = [self.expr(pt, 2)[0] for q, pt, pn in f.params]
                if self.chance(0.5):
                    args.append("1.0")
                else:
                    args.pop()
                out.append("%s%s(%s);" % (I, f.name, ", ".join(args)))
            else:
                out.append("%sundefinedFunction(1.0);" % I)
        elif kind == "mixed_arith" and self.take(kind):
            out.append(I + r.choice(["float %s = 1 + 1.0;" % self.name(),
                                     "int %s = 2 * 1u;" % self.name(),
                                     "vec3 %s = vec3(1.0) * 2;" % self.name(),
                                     "vec2 %s = vec2(1.0) + vec3(1.0).xy + ivec2(1);" % self.name(),
                                     "uint %s = 3u %% 2;" % self.name(),
                                     "float %s = 1.0 %% 2.0;" % self.name(),
                                     "bool %s = 1 < 2u;" % self.name(),
                                     "mat3 %s = mat3(1.0) * mat2(1.0);" % self.name(),
                                     "vec3 %s = mat3x2(1.0) * vec3(1.0);" % self.name()]))
        elif kind == "stage_builtin" and self.take(kind):
            if self.stage == "frag":
                out.append(I + r.choice(["gl_Position = vec4(1.0);", "float %s = float(gl_VertexID);" % self.name(),
                                         "gl_PointSize = 1.0;"]))
            else:
                out.append(I + r.choice(["vec4 %s = gl_FragCoord;" % self.name(),
                                         "float %s = dFdx(1.0);" % self.name(),
                                         "gl_FragDepth = 0.5;", "bool %s = gl_FrontFacing;" % self.name()]))
        elif kind == "literal_range" and self.take(kind):
            out.append(I + r.choice(["int %s = 4294967296;" % self.name(),
                                     "uint %s = 4294967296u;" % self.name(),
                                     "int %s = 0x1FFFFFFFF;" % self.name(),
                                     "int %s = 3000000000;" % self.name(),
                                     "int %s = 2147483648;" % self.name(),
                                     "int %s = -2147483648;" % self.name(),
                                     "float %s = 1e40;" % self.name(),
                                     "int %s = 09;" % self.name()]))
        elif kind == "array_of_array" and self.take(kind):
            out.append(I + r.choice(["float %s[2][3];" % self.name(), "float[2] %s[3];" % self.name(),
                                     "float %s[0];" % self.name(), "float %s[-1];" % self.name(),
                                     "float %s[];" % self.name()]))
        elif kind == "ternary_mismatch" and self.take(kind):
            out.append(I + r.choice(["float %s = true ? 1.0 : 2;" % self.name(),
                                     "float %s = 1.0 ? 1.0 : 2.0;" % self.name(),
                                     "vec2 %s = bvec2(true) ? vec2(1.0) : vec2(2.0);" % self.name(),
                                     "float %s = float[1](1.0) == float[1](2.0) ? float[1](1.0) : float[1](2.0);" % self.name()]))
        elif kind == "out_arg_not_lvalue" and self.take(kind):
            fs = [f for f in self.funcs if any(q in ("out", "inout") for q, _, _ in f.params)]
            if fs:
                f = r.choice(fs)
                args = []
                for q, pt, pn in f.params:
                    args.append(self.wrap(self.expr(pt, 2), P_ASSIGN) if q in ("out", "inout")
                                and pt not in self.structs else self.expr(pt, 2)[0])
                out.append("%s%s(%s);" % (I, f.name, ", ".join(args)))
            else:
                out.append("%sfloat %s = modf(1.5, 2.0);" % (I, self.name()))
        else:
            pass

    # ----------------------------------------------------------------- top level
    def struct_decl(self, out):
        nm = self.name("S")
        fields = []
        for _ in range(self.r.randint(1, 4)):
            t = self.pick_type(allow_struct=True)
            fa = self.r.randint(2, 3) if self.chance(0.15) else None
            fields.append((t, self.name("f"), fa))
        body = " ".join("%s %s%s;" % (t, fn, "[%d]" % fa if fa else "") for t, fn, fa in fields)
        out.append("struct %s { %s };" % (nm, body))
        self.structs[nm] = fields

    def global_decls(self, out):
        r = self.r
        io_loc = 0
        for _ in range(r.randint(0, 2)):
            self.struct_decl(out)
        # uniforms
        for _ in range(r.randint(0, 4)):
            t = self.pick_type(allow_struct=True)
            nm = self.name("u")
            arr = r.randint(2, 4) if self.chance(0.2) else None
            prec = (r.choice(PREC) + " ") if t in INFO and INFO[t][0] != "bool" and self.chance(0.3) else ""
            init = ""
            if self.take("uniform_init"):
                init = " = %s" % self.const_expr(t)[0] if arr is None else ""
            out.append("uniform %s%s %s%s%s;" % (prec, t, nm, "[%d]" % arr if arr else "", init))
            self.declare(Var(nm, t, array=arr, readonly=True))
        if self.chance(0.2):
            bn, inst = self.name("Block"), self.name("ub") if self.chance(0.5) else None
            fields = [(self.pick_type(allow_struct=False, allow_mat=True), self.name("bf")) for _ in range(r.randint(1, 3))]
            lay = r.choice(["", "layout(std140) ", "layout(std140, row_major) ", "layout(column_major) "]
                           + (["layout(shared) ", "layout(packed) "] if self.chance(0.1) else []))
            out.append("%suniform %s { %s }%s;" % (lay, bn, " ".join("%s %s;" % f for f in fields),
                                                  " " + inst if inst else ""))
            for t, fn in fields:
                self.declare(Var((inst + "." + fn) if inst else fn, t, readonly=True))
        # samplers
        for _ in range(r.randint(0, 2)):
            st = r.choice(list(SAMPLERS))
            nm = self.name("tex")
            prec = ""
            if st in NEEDS_SAMPLER_PRECISION or self.chance(0.3):
                prec = r.choice(PREC) + " "
            if st in NEEDS_SAMPLER_PRECISION and self.take("sampler_no_precision"):
                prec = ""
            out.append("uniform %s%s %s;" % (prec, st, nm))
            v = Var(nm, st, readonly=True)
            self.samplers.append(v)
            self.declare(v)
        # stage inputs / outputs
        if self.stage == "vert":
            for _ in range(r.randint(0, 3)):
                t = r.choice([x for x in NUMERIC] + list(MATS))
                nm = self.name("a")
                lay = "layout(location = %d) " % io_loc if self.chance(0.4) else ""
                io_loc += 4
                out.append("%sin %s %s;" % (lay, t, nm))
                self.declare(Var(nm, t, readonly=True))
            for _ in range(r.randint(0, 3)):
                t = r.choice(NUMERIC + list(MATS))
                nm = self.name("o")
                q = ""
                if INFO.get(t, ("float",))[0] != "float":
                    q = "flat "
                elif self.chance(0.3):
                    q = r.choice(["flat ", "smooth ", "centroid ", "invariant ", "flat centroid "])
                arr = r.randint(2, 3) if self.chance(0.15) else None
                out.append("%sout %s%s%s;" % (q, t, " " + nm, "[%d]" % arr if arr else ""))
                self.declare(Var(nm, t, array=arr))
            if self.chance(0.2):
                out.append("invariant gl_Position;")
        else:
            for _ in range(r.randint(0, 3)):
                t = r.choice(NUMERIC + list(MATS))
                nm = self.name("vin")
                q = ""
                if INFO.get(t, ("float",))[0] != "float":
                    q = "flat "
                elif self.chance(0.3):
                    q = r.choice(["flat ", "smooth ", "centroid ", "centroid in"[:0]])
                out.append("%sin %s %s;" % (q, t, nm))
                self.declare(Var(nm, t, readonly=True))
            k = r.random()
            if k < 0.6:
                t = r.choice(["vec4", "vec4", "vec4", "ivec4", "uvec2", "float", "vec3"])
                nm = self.name("frag")
                lay = "layout(location = 0) " if self.chance(0.4) else ""
                out.append("%sout %s%s %s;" % (lay, "highp " if self.chance(0.2) else "", t, nm))
                self.declare(Var(nm, t))
            elif k < 0.8:
                n = r.randint(2, 3)
                for j in range(n):
                    t = r.choice(["vec4", "vec4", "ivec4", "float"])
                    nm = self.name("frag")
                    out.append("layout(location = %d) out %s %s;" % (j, t, nm))
                    self.declare(Var(nm, t))
            else:
                nm = self.name("frag")
                out.append("layout(location = 0) out vec4 %s[2];" % nm)
                self.declare(Var(nm, "vec4", array=2, const_index=True))
        # global variables and consts
        for _ in range(r.randint(0, 3)):
            t = self.pick_type(allow_struct=True)
            nm = self.name("g")
            if self.chance(0.5) and t not in self.structs:
                out.append("const %s %s = %s;" % (t, nm, self.wrap(self.const_expr(t), P_ASSIGN)))
                self.declare(Var(nm, t, const=True))
            elif self.chance(0.5):
                out.append("%s %s = %s;" % (t, nm, self.wrap(self.const_expr(t), P_ASSIGN)))
                self.declare(Var(nm, t))
            else:
                out.append("%s %s;" % (t, nm))
                self.declare(Var(nm, t))

    def global_mutations(self, out):
        r = self.r
        if self.take("bad_io_type"):
            if self.stage == "frag":
                out.append(r.choice(["out bool badOut;", "out mat4 badOut;", "in int badIn;",
                                     "out vec4 badOut[2][2];", "flat out vec4 badOut;",
                                     "in bool badIn;"] +
                                    (["out %s badOut;" % list(self.structs)[0]] if self.structs else [])))
            else:
                out.append(r.choice(["in bool badIn;", "out int badOut;", "in vec4 badIn[2];",
                                     "out bool badOut;", "flat in vec4 badIn;", "centroid in vec4 badIn;"] +
                                    (["in %s badIn;" % list(self.structs)[0]] if self.structs else [])))
        if self.take("layout_error"):
            out.append(r.choice(["layout(location = 0) uniform float badU;",
                                 "layout(location = 0) float badG;",
                                 "layout(std140) out vec4 badO;",
                                 "layout(location = -1) out vec4 badO;",
                                 "layout(foo) uniform float badU;",
                                 "layout(binding = 0) uniform sampler2D badS;",
                                 "layout(location = 0) in vec4 badI;" if self.stage == "frag"
                                 else "layout(location = 0) out vec4 badO;"]))
        if self.take("gl_fragcolor"):
            out.append("void glFragColorUser() { gl_FragColor = vec4(1.0); }" if self.stage == "frag"
                       else "attribute vec4 badAttr;")
        if self.take("bad_precision_stmt"):
            out.append(r.choice(["precision mediump vec4;", "precision highp bool;", "precision lowp uint;",
                                 "precision mediump mat2;", "precision highp S;", "mediump bool badB;"]))
        if self.take("redefine_builtin"):
            out.append(r.choice(["float sin(float x) { return x; }", "vec3 normalize(vec3 v) { return v; }",
                                 "float abs(float x);", "int texture = 1;", "float dot;"]))
        if self.take("overload_return"):
            out.append("float ovl(float x) { return x; }")
            out.append("int ovl(float x) { return 1; }")
        if self.take("reserved_name") and False:
            pass

    def function(self, out):
        r = self.r
        ret = r.choice(["void", "void"] + [self.pick_type(allow_struct=True) for _ in range(3)])
        nm = self.name("fn")
        params = []
        for _ in range(r.randint(0, 3)):
            q = r.choice(["", "", "in ", "const in ", "out ", "inout ", "const "])
            t = self.pick_type(allow_struct=True)
            pn = self.name("p")
            prec = r.choice(PREC) + " " if t in INFO and INFO[t][0] != "bool" and self.chance(0.2) else ""
            params.append((q.strip(), t, pn, prec))
        sig = "%s %s(%s)" % (ret, nm, ", ".join("%s%s%s %s" % (q + " " if q else "", prec, t, pn)
                                                for q, t, pn, prec in params))
        if self.chance(0.2):
            out.append(sig + ";")
        out.append(sig + " {")
        self.scopes.append({})
        for q, t, pn, prec in params:
            self.declare(Var(pn, t, readonly=q.startswith("const")))
        self.cur_ret = ret
        self.block(1, out, r.randint(1, 4), new_scope=False)
        missing = self.take("missing_return") if ret != "void" else False
        if ret != "void" and not missing:
            out.append("    return %s;" % self.wrap(self.expr(ret, 1), P_COMMA))
        self.scopes.pop()
        out.append("}")
        self.funcs.append(Func(nm, ret, [(q if q else "in", t, pn) for q, t, pn, prec in params]))

    def program(self):
        r = self.r
        out = ["#version 300 es"]
        if self.take("extension"):
            out.append(r.choice(["#extension GL_OES_standard_derivatives : enable",
                                 "#extension GL_EXT_frag_depth : require",
                                 "#extension GL_EXT_shader_texture_lod : enable",
                                 "#extension all : warn", "#extension all : enable",
                                 "#extension GL_FOO_bar : require", "#extension GL_FOO_bar : warn",
                                 "#extension GL_OES_EGL_image_external_essl3 : enable",
                                 "#extension GL_EXT_draw_buffers : enable",
                                 "#extension GL_OVR_multiview2 : enable"]))
        if self.take("macro_error"):
            out.append(r.choice(["#define GL_FOO 1", "#define __BAR 1", "#undef __LINE__",
                                 "#define FOO(a, a) a", "#if 1", "#error boom", "#line 0 -1",
                                 "#pragma STDGL invariant(all)", "#define webgl_x 1", "#endif",
                                 "#define A 1\n#define A 2", "#if defined(", "#ifdef\n#endif"]))
        elif self.chance(0.1):
            out.append(r.choice(["#define K 2", "#define SQ(x) ((x) * (x))", "#pragma optimize(off)",
                                 "#ifdef GL_ES\n#define HAS_ES 1\n#endif", "#if __VERSION__ >= 300\n#define V3 1\n#endif",
                                 "#line 10", "#pragma debug(on)", "#undef K"]))
        no_prec = self.take("no_precision")
        if self.stage == "frag":
            if not no_prec:
                out.append("precision %s float;" % r.choice(["mediump", "highp", "lowp", "highp", "mediump"]))
        elif self.chance(0.3):
            out.append("precision %s float;" % r.choice(PREC))
        if self.chance(0.25):
            out.append("precision %s int;" % r.choice(PREC))
        if self.chance(0.05):
            out.append("precision mediump sampler3D;")
        self.global_decls(out)
        self.global_mutations(out)
        for _ in range(r.randint(0, 3)):
            self.function(out)
        out.append("void main() {")
        self.scopes.append({})
        self.cur_ret = "void"
        self.block(1, out, r.randint(2, 7), new_scope=False)
        # leftover statement-level mutations get one more chance in main
        for _ in range(3):
            if self.mut:
                before = len(self.mut)
                self.r_force = True
                saved = self.chance
                self.chance = lambda p: False if p == 0.75 else saved(p)
                self.maybe_mutate_stmt(1, out)
                self.chance = saved
                if len(self.mut) == before:
                    self.mut.pop(0)
        if self.stage == "vert" and self.chance(0.8):
            out.append("    gl_Position = %s;" % self.wrap(self.expr("vec4", 1), P_ASSIGN))
        self.scopes.pop()
        out.append("}")
        return "\n".join(out) + "\n"


def generate(seed, index, mutate_rate=0.35):
    rng = random.Random("%s:%s" % (seed, index))
    stage = "frag" if rng.random() < 0.6 else "vert"
    muts = []
    if rng.random() < mutate_rate:
        muts = [rng.choice(MUTATIONS)]
        if rng.random() < 0.15:
            muts.append(rng.choice(MUTATIONS))
    g = Gen(rng, stage, muts)
    src = g.program()
    head, rest = src.split("\n", 1)
    return stage, "%s\n// mutations: %s\n%s" % (head, ",".join(g.used_mutations), rest), g.used_mutations


def file_name(seed, index, stage):
    return "s%s_%06d.%s" % (seed, index, stage)


def write(seed, index, outdir, mutate_rate=0.35):
    stage, src, muts = generate(seed, index, mutate_rate)
    path = os.path.join(outdir, file_name(seed, index, stage))
    with open(path, "w") as fh:
        fh.write(src)
    return path, muts


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", default="1")
    ap.add_argument("--count", type=int, default=10)
    ap.add_argument("--start", type=int, default=0)
    ap.add_argument("--out", default=".")
    ap.add_argument("--mutate-rate", type=float, default=0.35)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    for i in range(a.start, a.start + a.count):
        print(write(a.seed, i, a.out, a.mutate_rate)[0])


if __name__ == "__main__":
    main()
