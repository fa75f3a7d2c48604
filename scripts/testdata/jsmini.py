"""A small JavaScript interpreter: enough of ES5/ES6 to run the WebGL conformance pages'
test-building scripts (literals, functions and closures, loops, string and array methods).
It is not a general JavaScript engine: what it lacks raises JSError."""

import math
import re


class JSError(Exception):
    pass


class _Undefined:
    def __repr__(self):
        return 'undefined'

    def __bool__(self):
        return False


undefined = _Undefined()


class JSObject(dict):
    pass


class JSArray(list):
    pass


class JSFunction:
    def __init__(self, name, params, body, env, interp, arrow=False, this=None, expr_body=False):
        self.name, self.params, self.body, self.env = name, params, body, env
        self.interp, self.arrow, self.this, self.expr_body = interp, arrow, this, expr_body
        self.props = JSObject()

    def __call__(self, this, args):
        return self.interp.call_function(self, this, args)


class Native:
    def __init__(self, fn, name=''):
        self.fn, self.name = fn, name
        self.props = JSObject()

    def __call__(self, this, args):
        return self.fn(this, *args)


class JSRegExp:
    def __init__(self, source, flags):
        self.source, self.flags = source, flags
        pyflags = (re.I if 'i' in flags else 0) | (re.M if 'm' in flags else 0)
        src = source.replace('(?<', '(?P<') if '(?<=' not in source and '(?<!' not in source else source
        self.re = re.compile(src, pyflags)
        self.glob = 'g' in flags
        self.lastIndex = 0


class _Break(Exception):
    def __init__(self, label=None):
        self.label = label


class _Continue(Exception):
    def __init__(self, label=None):
        self.label = label


class _Return(Exception):
    def __init__(self, value):
        self.value = value


class JSThrow(Exception):
    def __init__(self, value):
        self.value = value


# ---------------------------------------------------------------- lexer

PUNCT = sorted('''>>>= ... === !== **= <<= >>= >>> => == != <= >= && || ?? ?. ++ -- += -= *= /= %= &= |= ^= << >> ** { } ( ) [ ] ; , < > + - * / % & | ^ ! ~ ? : = . @ #'''.split(), key=len, reverse=True)
KEYWORDS = {'var', 'let', 'const', 'function', 'return', 'if', 'else', 'for', 'while', 'do', 'break',
            'continue', 'new', 'typeof', 'instanceof', 'in', 'of', 'true', 'false', 'null', 'undefined',
            'this', 'switch', 'case', 'default', 'throw', 'try', 'catch', 'finally', 'delete', 'void', 'class'}
_REGEX_PREV = {'(', ',', '=', ':', '[', '!', '&', '|', '?', '{', '}', ';', '+', '-', '*', '%', '<', '>',
               '&&', '||', '==', '===', '!=', '!==', 'return', 'typeof', '=>', '+=', '??', None}
_ESC = {'n': '\n', 't': '\t', 'r': '\r', 'b': '\b', 'f': '\f', 'v': '\v', '0': '\0'}


def _escape_at(s, i):
    """The text of the escape sequence at s[i] == '\\', and the index after it."""
    d = s[i + 1]
    if d in _ESC and not (d == '0' and i + 2 < len(s) and s[i + 2].isdigit()):
        return _ESC[d], i + 2
    if d == 'x':
        return chr(int(s[i + 2:i + 4], 16)), i + 4
    if d == 'u':
        if s[i + 2] == '{':
            e = s.index('}', i)
            return chr(int(s[i + 3:e], 16)), e + 1
        return chr(int(s[i + 2:i + 6], 16)), i + 6
    if d == '\r':
        return '', (i + 3 if s[i + 2:i + 3] == '\n' else i + 2)
    if d == '\n':
        return '', i + 2
    return d, i + 2


def _unescape(s, i, quote):
    out = []
    n = len(s)
    while True:
        if i >= n:
            raise JSError('unterminated string')
        c = s[i]
        if c == quote:
            return ''.join(out), i + 1
        if c == '\\':
            t, i = _escape_at(s, i)
            out.append(t)
        else:
            out.append(c)
            i += 1


def tokenize(s):
    toks = []
    i, n = 0, len(s)
    prev = None
    while i < n:
        c = s[i]
        if c in ' \t\r\n\ufeff\xa0':
            i += 1
            continue
        if s.startswith('//', i) or s.startswith('<!--', i):
            e = s.find('\n', i)
            i = n if e < 0 else e
            continue
        if s.startswith('/*', i):
            e = s.find('*/', i + 2)
            i = n if e < 0 else e + 2
            continue
        if c.isalpha() or c in '_$':
            e = i + 1
            while e < n and (s[e].isalnum() or s[e] in '_$'):
                e += 1
            w = s[i:e]
            toks.append(('kw' if w in KEYWORDS else 'id', w))
            i = e
        elif c.isdigit() or (c == '.' and i + 1 < n and s[i + 1].isdigit()):
            m = re.compile(r'0[xX][0-9a-fA-F]+|0[bB][01]+|0[oO][0-7]+|(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?').match(s, i)
            t = m.group(0)
            if t[:2] in ('0x', '0X'):
                v = float(int(t, 16))
            elif t[:2] in ('0b', '0B'):
                v = float(int(t[2:], 2))
            elif t[:2] in ('0o', '0O'):
                v = float(int(t[2:], 8))
            else:
                v = float(t)
            toks.append(('num', v))
            i = m.end()
        elif c in '"\'':
            v, i = _unescape(s, i + 1, c)
            toks.append(('str', v))
        elif c == '`':
            parts, exprs = [], []
            i += 1
            buf = []
            while True:
                if i >= n:
                    raise JSError('unterminated template')
                d = s[i]
                if d == '`':
                    i += 1
                    break
                if d == '\\':
                    t, i = _escape_at(s, i)
                    buf.append(t)
                    continue
                if s.startswith('${', i):
                    depth, j = 1, i + 2
                    while depth:
                        if s[j] == '{':
                            depth += 1
                        elif s[j] == '}':
                            depth -= 1
                        elif s[j] in '"\'`':
                            q = s[j]
                            j += 1
                            while s[j] != q:
                                j += 2 if s[j] == '\\' else 1
                        j += 1
                    parts.append(''.join(buf))
                    buf = []
                    exprs.append(tokenize(s[i + 2:j - 1]))
                    i = j
                    continue
                buf.append(d)
                i += 1
            parts.append(''.join(buf))
            toks.append(('tpl', (parts, exprs)))
        elif c == '/' and (prev is None or (prev[0] in ('op', 'kw') and prev[1] in _REGEX_PREV)):
            j, cls = i + 1, False
            while True:
                d = s[j]
                if d == '\\':
                    j += 2
                    continue
                if d == '[':
                    cls = True
                elif d == ']':
                    cls = False
                elif d == '/' and not cls:
                    break
                j += 1
            body = s[i + 1:j]
            k = j + 1
            while k < n and s[k].isalpha():
                k += 1
            toks.append(('re', (body, s[j + 1:k])))
            i = k
        else:
            for p in PUNCT:
                if s.startswith(p, i):
                    toks.append(('op', p))
                    i += len(p)
                    break
            else:
                raise JSError('bad character %r' % c)
        prev = toks[-1]
    toks.append(('eof', None))
    return toks


# ---------------------------------------------------------------- parser (AST = tuples)

BINARY = {'??': 1, '||': 2, '&&': 3, '|': 4, '^': 5, '&': 6, '==': 7, '!=': 7, '===': 7, '!==': 7,
          '<': 8, '>': 8, '<=': 8, '>=': 8, 'instanceof': 8, 'in': 8, '<<': 9, '>>': 9, '>>>': 9,
          '+': 10, '-': 10, '*': 11, '/': 11, '%': 11, '**': 12}
ASSIGN = {'=', '+=', '-=', '*=', '/=', '%=', '<<=', '>>=', '>>>=', '&=', '|=', '^=', '**='}


class Parser:
    def __init__(self, toks):
        self.t = toks
        self.i = 0

    def peek(self, k=0):
        return self.t[self.i + k]

    def next(self):
        tok = self.t[self.i]
        self.i += 1
        return tok

    def is_(self, v, kind=None):
        tok = self.t[self.i]
        return tok[1] == v and tok[0] in ((kind,) if kind else ('op', 'kw'))

    def accept(self, v):
        if self.is_(v):
            self.i += 1
            return True
        return False

    def expect(self, v):
        if not self.accept(v):
            raise JSError('expected %r, got %r' % (v, self.peek()))

    def ident(self):
        tok = self.next()
        if tok[0] not in ('id', 'kw'):
            raise JSError('expected identifier, got %r' % (tok,))
        return tok[1]

    def program(self):
        body = []
        while self.peek()[0] != 'eof':
            body.append(self.statement())
        return body

    def semi(self):
        self.accept(';')

    def block(self):
        self.expect('{')
        body = []
        while not self.accept('}'):
            body.append(self.statement())
        return ('block', body)

    def statement(self):
        tok = self.peek()
        if tok == ('op', '{'):
            return self.block()
        if tok == ('op', ';'):
            self.next()
            return ('empty',)
        if tok[0] == 'kw':
            k = tok[1]
            if k in ('var', 'let', 'const'):
                s = self.var_decl()
                self.semi()
                return s
            if k == 'function':
                self.next()
                name = self.ident()
                f = self.function_rest(name)
                return ('fundecl', name, f)
            if k == 'class':
                return self.class_decl()
            if k == 'return':
                self.next()
                if self.is_(';') or self.is_('}') or self.peek()[0] == 'eof':
                    self.semi()
                    return ('return', None)
                e = self.expression()
                self.semi()
                return ('return', e)
            if k == 'if':
                self.next()
                self.expect('(')
                c = self.expression()
                self.expect(')')
                a = self.statement()
                b = self.statement() if self.accept('else') else None
                return ('if', c, a, b)
            if k == 'for':
                return self.for_stmt()
            if k == 'while':
                self.next()
                self.expect('(')
                c = self.expression()
                self.expect(')')
                return ('while', c, self.statement())
            if k == 'do':
                self.next()
                body = self.statement()
                self.expect('while')
                self.expect('(')
                c = self.expression()
                self.expect(')')
                self.semi()
                return ('dowhile', body, c)
            if k in ('break', 'continue'):
                self.next()
                label = None
                if self.peek()[0] == 'id':
                    label = self.next()[1]
                self.semi()
                return (k, label)
            if k == 'throw':
                self.next()
                e = self.expression()
                self.semi()
                return ('throw', e)
            if k == 'try':
                self.next()
                b = self.block()
                param = handler = fin = None
                if self.accept('catch'):
                    if self.accept('('):
                        param = self.ident()
                        self.expect(')')
                    handler = self.block()
                if self.accept('finally'):
                    fin = self.block()
                return ('try', b, param, handler, fin)
            if k == 'switch':
                self.next()
                self.expect('(')
                d = self.expression()
                self.expect(')')
                self.expect('{')
                cases = []
                while not self.accept('}'):
                    if self.accept('default'):
                        test = None
                    else:
                        self.expect('case')
                        test = self.expression()
                    self.expect(':')
                    body = []
                    while not (self.is_('case') or self.is_('default') or self.is_('}')):
                        body.append(self.statement())
                    cases.append((test, body))
                return ('switch', d, cases)
        if tok[0] == 'id' and self.peek(1) == ('op', ':'):
            self.next()
            self.next()
            return ('labeled', tok[1], self.statement())
        e = self.expression()
        self.semi()
        return ('expr', e)

    def class_decl(self):
        self.next()
        name = self.ident()
        parent = self.lhs() if self.accept('extends') else None
        self.expect('{')
        methods = []
        while not self.accept('}'):
            if self.accept(';'):
                continue
            static = False
            if self.is_('static', 'id') and self.peek(1) != ('op', '('):
                self.next()
                static = True
            mname = self.ident()
            methods.append((static, mname, self.function_rest(mname)))
        return ('class', name, parent, methods)

    def var_decl(self):
        kind = self.next()[1]
        decls = []
        while True:
            target = self.binding_target()
            init = self.assign() if self.accept('=') else None
            decls.append((target, init))
            if not self.accept(','):
                break
        return ('var', kind, decls)

    def binding_target(self):
        if self.is_('['):
            self.next()
            names = []
            while not self.accept(']'):
                if self.is_(','):
                    self.next()
                    names.append(None)
                    continue
                names.append(self.binding_target())
                self.accept(',')
            return ('arraypat', names)
        if self.is_('{'):
            self.next()
            names = []
            while not self.accept('}'):
                key = self.ident()
                target = self.binding_target() if self.accept(':') else key
                default = self.assign() if self.accept('=') else None
                names.append((key, target, default))
                self.accept(',')
            return ('objpat', names)
        return self.ident()

    def for_stmt(self):
        self.next()
        self.expect('(')
        init = None
        if self.is_('var') or self.is_('let') or self.is_('const'):
            save = self.i
            kind = self.next()[1]
            target = self.binding_target()
            if self.is_('of') or self.is_('in'):
                how = self.next()[1]
                obj = self.expression()
                self.expect(')')
                return ('forin' if how == 'in' else 'forof', kind, target, obj, self.statement())
            self.i = save
            init = self.var_decl()
        elif not self.is_(';'):
            init = ('expr', self.expression(no_in=True))
            if self.is_('of') or self.is_('in'):
                how = self.next()[1]
                obj = self.expression()
                self.expect(')')
                return ('forin' if how == 'in' else 'forof', None, init[1], obj, self.statement())
        self.expect(';')
        cond = None if self.is_(';') else self.expression()
        self.expect(';')
        upd = None if self.is_(')') else self.expression()
        self.expect(')')
        return ('for', init, cond, upd, self.statement())

    def function_rest(self, name):
        self.expect('(')
        params = self.params()
        body = self.block()
        return ('function', name, params, body, False)

    def params(self):
        params = []
        while not self.accept(')'):
            if self.accept('...'):
                params.append(('rest', self.ident()))
            else:
                target = self.binding_target()
                default = self.assign() if self.accept('=') else None
                params.append((target, default))
            self.accept(',')
        return params

    def expression(self, no_in=False):
        e = self.assign(no_in)
        if self.is_(','):
            items = [e]
            while self.accept(','):
                items.append(self.assign(no_in))
            return ('seq', items)
        return e

    def _arrow_ahead(self):
        # at '(' : find matching ')' and check for '=>'
        depth, j = 0, self.i
        while True:
            tok = self.t[j]
            if tok[0] == 'eof':
                return False
            if tok[0] == 'op' and tok[1] in '([{':
                depth += 1
            elif tok[0] == 'op' and tok[1] in ')]}':
                depth -= 1
                if depth == 0:
                    return self.t[j + 1] == ('op', '=>')
            j += 1

    def assign(self, no_in=False):
        tok = self.peek()
        if tok[0] == 'id' and self.peek(1) == ('op', '=>'):
            self.next()
            self.next()
            return self.arrow_body([(tok[1], None)])
        if tok == ('op', '(') and self._arrow_ahead():
            self.next()
            params = self.params()
            self.expect('=>')
            return self.arrow_body(params)
        left = self.conditional(no_in)
        tok = self.peek()
        if tok[0] == 'op' and tok[1] in ASSIGN:
            self.next()
            right = self.assign(no_in)
            return ('assign', tok[1], left, right)
        return left

    def arrow_body(self, params):
        if self.is_('{'):
            return ('function', None, params, self.block(), True)
        return ('function', None, params, ('block', [('return', self.assign())]), True)

    def conditional(self, no_in=False):
        c = self.binary(0, no_in)
        if self.accept('?'):
            a = self.assign()
            self.expect(':')
            b = self.assign(no_in)
            return ('cond', c, a, b)
        return c

    def binary(self, minprec, no_in=False):
        left = self.unary()
        while True:
            tok = self.peek()
            op = tok[1]
            if tok[0] not in ('op', 'kw') or op not in BINARY or (no_in and op == 'in'):
                return left
            prec = BINARY[op]
            if prec <= minprec:
                return left
            self.next()
            right = self.binary(prec - (1 if op == '**' else 0), no_in)
            left = ('logic' if op in ('&&', '||', '??') else 'bin', op, left, right)

    def unary(self):
        tok = self.peek()
        if tok[0] in ('op', 'kw') and tok[1] in ('!', '-', '+', '~', 'typeof', 'void', 'delete'):
            self.next()
            return ('unary', tok[1], self.unary())
        if tok[0] == 'op' and tok[1] in ('++', '--'):
            self.next()
            return ('update', tok[1], True, self.unary())
        e = self.postfix()
        return e

    def postfix(self):
        e = self.lhs()
        tok = self.peek()
        if tok[0] == 'op' and tok[1] in ('++', '--'):
            self.next()
            return ('update', tok[1], False, e)
        return e

    def args(self):
        args = []
        while not self.accept(')'):
            if self.accept('...'):
                args.append(('spread', self.assign()))
            else:
                args.append(self.assign())
            self.accept(',')
        return args

    def lhs(self):
        if self.accept('new'):
            callee = self.member_only()
            args = self.args() if self.accept('(') else []
            e = ('new', callee, args)
        else:
            e = self.primary()
        return self.call_tail(e)

    def member_only(self):
        e = self.primary()
        while True:
            if self.accept('.'):
                e = ('member', e, ('lit', self.ident()))
            elif self.accept('['):
                k = self.expression()
                self.expect(']')
                e = ('member', e, k)
            else:
                return e

    def call_tail(self, e):
        while True:
            if self.accept('.') or self.accept('?.'):
                if self.accept('('):
                    e = ('call', e, self.args())
                    continue
                e = ('member', e, ('lit', self.ident()))
            elif self.accept('['):
                k = self.expression()
                self.expect(']')
                e = ('member', e, k)
            elif self.accept('('):
                e = ('call', e, self.args())
            elif self.peek()[0] == 'tpl':
                e = ('call', e, [('lit', JSArray(self.next()[1][0]))])
            else:
                return e

    def primary(self):
        tok = self.next()
        kind, v = tok
        if kind == 'num' or kind == 'str':
            return ('lit', v)
        if kind == 'tpl':
            parts, exprs = v
            return ('tpl', parts, [Parser(x).expression() for x in exprs])
        if kind == 're':
            return ('regex', v[0], v[1])
        if kind == 'id':
            return ('name', v)
        if kind == 'kw':
            if v == 'true':
                return ('lit', True)
            if v == 'false':
                return ('lit', False)
            if v == 'null':
                return ('lit', None)
            if v == 'undefined':
                return ('lit', undefined)
            if v == 'this':
                return ('this',)
            if v == 'function':
                name = self.ident() if self.peek()[0] == 'id' else None
                return self.function_rest(name)
            if v == 'class':
                self.i -= 1
                c = self.class_decl()
                return ('classexpr', c)
            return ('name', v)
        if tok == ('op', '('):
            e = self.expression()
            self.expect(')')
            return e
        if tok == ('op', '['):
            items = []
            while not self.accept(']'):
                if self.is_(','):
                    self.next()
                    items.append(('lit', undefined))
                    continue
                if self.accept('...'):
                    items.append(('spread', self.assign()))
                else:
                    items.append(self.assign())
                self.accept(',')
            return ('array', items)
        if tok == ('op', '{'):
            props = []
            while not self.accept('}'):
                if self.accept('...'):
                    props.append(('spread', self.assign()))
                    self.accept(',')
                    continue
                ktok = self.next()
                if ktok == ('op', '['):
                    key = self.assign()
                    self.expect(']')
                elif ktok[0] == 'num':
                    key = ('lit', _num_to_str(ktok[1]))
                else:
                    key = ('lit', ktok[1])
                if self.is_('('):
                    props.append((key, self.function_rest(None)))
                elif self.accept(':'):
                    props.append((key, self.assign()))
                else:
                    props.append((key, ('name', ktok[1])))
                self.accept(',')
            return ('object', props)
        raise JSError('unexpected token %r' % (tok,))


def _num_to_str(x):
    if isinstance(x, bool):
        return 'true' if x else 'false'
    if x != x:
        return 'NaN'
    if x in (math.inf, -math.inf):
        return 'Infinity' if x > 0 else '-Infinity'
    if float(x).is_integer() and abs(x) < 1e21:
        return str(int(x))
    r = repr(float(x))
    if 'e' in r:
        m, e = r.split('e')
        return m + 'e' + ('+' if not e.startswith('-') else '') + str(int(e)) if int(e) > 0 else m + 'e-' + str(-int(e))
    return r


# ---------------------------------------------------------------- evaluator

class Env:
    def __init__(self, parent=None):
        self.vars = {}
        self.parent = parent

    def lookup(self, name):
        e = self
        while e is not None:
            if name in e.vars:
                return e
            e = e.parent
        return None

    def get(self, name):
        e = self.lookup(name)
        if e is None:
            raise JSError('%s is not defined' % name)
        return e.vars[name]

    def set(self, name, value):
        e = self.lookup(name)
        (e or self.root()).vars[name] = value

    def root(self):
        e = self
        while e.parent is not None:
            e = e.parent
        return e


def to_str(v):
    if isinstance(v, str):
        return v
    if v is undefined:
        return 'undefined'
    if v is None:
        return 'null'
    if isinstance(v, bool):
        return 'true' if v else 'false'
    if isinstance(v, (int, float)):
        return _num_to_str(v)
    if isinstance(v, list):
        return ','.join('' if x is None or x is undefined else to_str(x) for x in v)
    if isinstance(v, JSRegExp):
        return '/%s/%s' % (v.source, v.flags)
    if isinstance(v, (JSFunction, Native)):
        return 'function'
    return '[object Object]'


def to_num(v):
    if isinstance(v, bool):
        return 1.0 if v else 0.0
    if isinstance(v, (int, float)):
        return float(v)
    if v is None:
        return 0.0
    if isinstance(v, str):
        s = v.strip()
        if s == '':
            return 0.0
        try:
            return float(int(s, 16)) if s[:2].lower() == '0x' else float(s)
        except ValueError:
            return math.nan
    if isinstance(v, list) and len(v) <= 1:
        return to_num(to_str(v))
    return math.nan


def truthy(v):
    if v is undefined or v is None:
        return False
    if isinstance(v, bool):
        return v
    if isinstance(v, (int, float)):
        return not (v == 0 or v != v)
    if isinstance(v, str):
        return v != ''
    return True


def to_int32(v):
    n = to_num(v)
    if n != n or n in (math.inf, -math.inf):
        return 0
    n = int(n) & 0xffffffff
    return n - (1 << 32) if n & 0x80000000 else n


def strict_eq(a, b):
    if isinstance(a, (int, float)) and not isinstance(a, bool) and isinstance(b, (int, float)) and not isinstance(b, bool):
        return float(a) == float(b)
    if type(a) != type(b):
        return False
    if isinstance(a, (str, bool)) or a is None or a is undefined:
        return a == b
    return a is b


def loose_eq(a, b):
    if (a is None or a is undefined) and (b is None or b is undefined):
        return True
    if a is None or a is undefined or b is None or b is undefined:
        return False
    if type(a) == type(b) or (isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool) and not isinstance(b, bool)):
        return strict_eq(a, b)
    if isinstance(a, (list, dict)) or isinstance(b, (list, dict)):
        return to_str(a) == to_str(b) if not (isinstance(a, (list, dict)) and isinstance(b, (list, dict))) else a is b
    return to_num(a) == to_num(b)


def _idx(k):
    if isinstance(k, float) and k.is_integer():
        return int(k)
    if isinstance(k, str) and k.isdigit():
        return int(k)
    return k


def _key(k):
    return to_str(k) if not isinstance(k, str) else k


class Interpreter:
    def __init__(self):
        self.glob = Env()
        import jsbuiltins
        jsbuiltins.install(self)

    def run(self, src, env=None):
        prog = Parser(tokenize(src)).program()
        return self.exec_body(prog, env or self.glob)

    # -- statements
    def hoist(self, body, env):
        for s in body:
            if s[0] == 'fundecl':
                env.vars[s[1]] = self.make_function(s[2], env)
            elif s[0] == 'var' and s[1] == 'var':
                for target, _ in s[2]:
                    if isinstance(target, str) and target not in env.vars:
                        env.vars[target] = undefined

    def exec_body(self, body, env):
        self.hoist(body, env)
        for s in body:
            self.exec(s, env)

    def exec(self, s, env):
        k = s[0]
        if k == 'expr':
            self.eval(s[1], env)
        elif k == 'var':
            for target, init in s[2]:
                v = self.eval(init, env) if init is not None else undefined
                if init is None and s[1] == 'var' and isinstance(target, str) and target in env.vars:
                    continue
                self.bind(target, v, env)
        elif k == 'fundecl':
            pass
        elif k == 'return':
            raise _Return(self.eval(s[1], env) if s[1] is not None else undefined)
        elif k == 'if':
            if truthy(self.eval(s[1], env)):
                self.exec(s[2], env)
            elif s[3] is not None:
                self.exec(s[3], env)
        elif k == 'block':
            inner = Env(env)
            self.hoist([x for x in s[1] if x[0] == 'fundecl'], inner)
            for x in s[1]:
                if x[0] == 'var' and x[1] == 'var':
                    self._exec_var_outer(x, inner, env)
                else:
                    self.exec(x, inner)
        elif k == 'for':
            loop_env = Env(env)
            if s[1] is not None:
                if s[1][0] == 'var' and s[1][1] == 'var':
                    self._exec_var_outer(s[1], loop_env, env)
                else:
                    self.exec(s[1], loop_env)
            count = 0
            while s[2] is None or truthy(self.eval(s[2], loop_env)):
                count += 1
                if count > 1000000:
                    raise JSError('loop too long')
                try:
                    self.exec(s[4], loop_env)
                except _Break as b:
                    if b.label is None:
                        break
                    raise
                except _Continue as c:
                    if c.label is not None:
                        raise
                if s[3] is not None:
                    self.eval(s[3], loop_env)
        elif k in ('forof', 'forin'):
            obj = self.eval(s[3], env)
            if k == 'forin':
                items = [str(i) for i in range(len(obj))] if isinstance(obj, (list, str)) else list(obj.keys())
            else:
                items = list(obj) if isinstance(obj, (list, str)) else list(obj.values())
            for it in items:
                loop_env = Env(env)
                if s[1] is None:
                    self.assign_to(s[2], it, env)
                else:
                    self.bind(s[2], it, loop_env if s[1] != 'var' else env)
                try:
                    self.exec(s[4], loop_env)
                except _Break as b:
                    if b.label is None:
                        break
                    raise
                except _Continue as c:
                    if c.label is not None:
                        raise
        elif k == 'while':
            while truthy(self.eval(s[1], env)):
                try:
                    self.exec(s[2], env)
                except _Break:
                    break
                except _Continue:
                    pass
        elif k == 'dowhile':
            while True:
                try:
                    self.exec(s[1], env)
                except _Break:
                    break
                except _Continue:
                    pass
                if not truthy(self.eval(s[2], env)):
                    break
        elif k == 'break':
            raise _Break(s[1])
        elif k == 'continue':
            raise _Continue(s[1])
        elif k == 'labeled':
            try:
                self.exec(s[2], env)
            except _Break as b:
                if b.label != s[1]:
                    raise
        elif k == 'throw':
            raise JSThrow(self.eval(s[1], env))
        elif k == 'try':
            try:
                self.exec(s[1], env)
            except (JSThrow, JSError) as ex:
                if s[3] is None:
                    raise
                cenv = Env(env)
                if s[2]:
                    cenv.vars[s[2]] = ex.value if isinstance(ex, JSThrow) else JSObject(message=str(ex))
                self.exec(s[3], cenv)
            finally:
                if s[4] is not None:
                    self.exec(s[4], env)
        elif k == 'switch':
            d = self.eval(s[1], env)
            matched = False
            try:
                for test, body in s[2] + [(None, None)]:
                    if body is None:
                        if matched:
                            break
                        # run default
                        started = False
                        for t2, b2 in s[2]:
                            if t2 is None:
                                started = True
                            if started:
                                for x in b2:
                                    self.exec(x, env)
                        break
                    if not matched and test is not None and strict_eq(d, self.eval(test, env)):
                        matched = True
                    if matched:
                        for x in body:
                            self.exec(x, env)
            except _Break as b:
                if b.label is not None:
                    raise
        elif k == 'class':
            env.vars[s[1]] = self.make_class(s, env)
        elif k == 'empty':
            pass
        else:
            raise JSError('statement %s' % k)

    def _exec_var_outer(self, s, inner, outer):
        # `var` is function scoped: bind in the enclosing function's scope
        for target, init in s[2]:
            if init is None:
                if isinstance(target, str) and outer.lookup(target) is None:
                    outer.vars[target] = undefined
                continue
            v = self.eval(init, inner)
            if isinstance(target, str):
                e = inner.lookup(target)
                (e or outer).vars[target] = v
            else:
                self.bind(target, v, outer)

    def bind(self, target, v, env):
        if isinstance(target, str):
            env.vars[target] = v
        elif target[0] == 'arraypat':
            for i, t in enumerate(target[1]):
                if t is not None:
                    self.bind(t, v[i] if i < len(v) else undefined, env)
        elif target[0] == 'objpat':
            for key, t, default in target[1]:
                x = self.get_prop(v, key)
                if x is undefined and default is not None:
                    x = self.eval(default, env)
                self.bind(t, x, env)

    def make_function(self, f, env):
        return JSFunction(f[1], f[2], f[3], env, self, arrow=f[4])

    def make_class(self, s, env):
        _, name, parent, methods = s
        ctor = None
        proto = JSObject()
        statics = JSObject()
        for static, mname, f in methods:
            fn = self.make_function(f, env)
            if mname == 'constructor':
                ctor = fn
            elif static:
                statics[mname] = fn
            else:
                proto[mname] = fn
        if ctor is None:
            ctor = Native(lambda this, *a: undefined, name)
        ctor.props['prototype'] = proto
        ctor.props.update(statics)
        return ctor

    def call_function(self, fn, this, args):
        env = Env(fn.env)
        if not fn.arrow:
            env.vars['this'] = this
            env.vars['arguments'] = JSArray(args)
        for i, p in enumerate(fn.params):
            if p[0] == 'rest':
                env.vars[p[1]] = JSArray(args[i:])
                break
            target, default = p
            v = args[i] if i < len(args) else undefined
            if v is undefined and default is not None:
                v = self.eval(default, env)
            self.bind(target, v, env)
        try:
            self.exec_body(fn.body[1], env)
        except _Return as r:
            return r.value
        return undefined

    def call(self, f, this, args):
        if isinstance(f, (JSFunction, Native)):
            return f(this, args)
        raise JSError('not a function: %r' % (f,))

    # -- expressions
    def eval(self, e, env):
        k = e[0]
        if k == 'lit':
            return e[1]
        if k == 'name':
            return env.get(e[1])
        if k == 'this':
            t = env.lookup('this')
            return t.vars['this'] if t else undefined
        if k == 'tpl':
            out = [e[1][0]]
            for i, x in enumerate(e[2]):
                out.append(to_str(self.eval(x, env)))
                out.append(e[1][i + 1])
            return ''.join(out)
        if k == 'array':
            arr = JSArray()
            for x in e[1]:
                if x[0] == 'spread':
                    arr.extend(self.eval(x[1], env))
                else:
                    arr.append(self.eval(x, env))
            return arr
        if k == 'object':
            obj = JSObject()
            for key, val in e[1]:
                if key == 'spread':
                    obj.update(self.eval(val, env))
                    continue
                kv = _key(self.eval(key, env))
                v = self.eval(val, env) if val[0] != 'function' else self.make_function(val, env)
                obj[kv] = v
            return obj
        if k == 'function':
            return self.make_function(e, env)
        if k == 'classexpr':
            return self.make_class(e[1], env)
        if k == 'regex':
            return JSRegExp(e[1], e[2])
        if k == 'member':
            obj = self.eval(e[1], env)
            return self.get_prop(obj, self.eval(e[2], env))
        if k == 'call':
            callee = e[1]
            if callee[0] == 'member':
                this = self.eval(callee[1], env)
                f = self.get_prop(this, self.eval(callee[2], env))
            else:
                this = undefined
                f = self.eval(callee, env)
            args = []
            for a in e[2]:
                if a[0] == 'spread':
                    args.extend(self.eval(a[1], env))
                else:
                    args.append(self.eval(a, env))
            if not isinstance(f, (JSFunction, Native)):
                raise JSError('not a function: %s' % (callee,))
            return f(this, args)
        if k == 'new':
            f = self.eval(e[1], env)
            args = [self.eval(a, env) for a in e[2]]
            if isinstance(f, Native) and 'construct' in f.props:
                return f.props['construct'](args)
            obj = JSObject()
            proto = f.props.get('prototype') if hasattr(f, 'props') else None
            if proto:
                obj.update({kk: vv for kk, vv in proto.items()})
            r = f(obj, args)
            return r if isinstance(r, (dict, list)) else obj
        if k == 'assign':
            op, target, val = e[1], e[2], e[3]
            if op == '=':
                v = self.eval(val, env)
            else:
                v = self.binop(op[:-1], self.eval(target, env), self.eval(val, env))
            self.assign_to(target, v, env)
            return v
        if k == 'update':
            old = to_num(self.eval(e[3], env))
            new = old + (1 if e[1] == '++' else -1)
            self.assign_to(e[3], new, env)
            return new if e[2] else old
        if k == 'logic':
            a = self.eval(e[2], env)
            if e[1] == '&&':
                return self.eval(e[3], env) if truthy(a) else a
            if e[1] == '||':
                return a if truthy(a) else self.eval(e[3], env)
            return self.eval(e[3], env) if a is None or a is undefined else a
        if k == 'bin':
            return self.binop(e[1], self.eval(e[2], env), self.eval(e[3], env))
        if k == 'unary':
            op = e[1]
            if op == 'typeof':
                if e[2][0] == 'name' and env.lookup(e[2][1]) is None:
                    return 'undefined'
                v = self.eval(e[2], env)
                if v is undefined:
                    return 'undefined'
                if isinstance(v, bool):
                    return 'boolean'
                if isinstance(v, (int, float)):
                    return 'number'
                if isinstance(v, str):
                    return 'string'
                if isinstance(v, (JSFunction, Native)):
                    return 'function'
                return 'object'
            if op == 'delete':
                if e[2][0] == 'member':
                    obj = self.eval(e[2][1], env)
                    obj.pop(_key(self.eval(e[2][2], env)), None)
                return True
            v = self.eval(e[2], env)
            if op == '!':
                return not truthy(v)
            if op == '-':
                return -to_num(v)
            if op == '+':
                return to_num(v)
            if op == '~':
                return float(~to_int32(v))
            if op == 'void':
                return undefined
        if k == 'cond':
            return self.eval(e[2], env) if truthy(self.eval(e[1], env)) else self.eval(e[3], env)
        if k == 'seq':
            v = undefined
            for x in e[1]:
                v = self.eval(x, env)
            return v
        raise JSError('expression %s' % k)

    def assign_to(self, target, v, env):
        if isinstance(target, tuple) and target[0] == 'name':
            env.set(target[1], v)
        elif isinstance(target, tuple) and target[0] == 'member':
            obj = self.eval(target[1], env)
            key = self.eval(target[2], env)
            self.set_prop(obj, key, v)
        elif isinstance(target, tuple) and target[0] == 'array':
            for i, t in enumerate(target[1]):
                self.assign_to(t, v[i] if i < len(v) else undefined, env)
        elif isinstance(target, str):
            env.set(target, v)
        else:
            raise JSError('bad assignment target')

    def set_prop(self, obj, key, v):
        if isinstance(obj, list):
            i = _idx(key)
            if isinstance(i, int):
                while len(obj) <= i:
                    obj.append(undefined)
                obj[i] = v
                return
            if key == 'length':
                del obj[int(to_num(v)):]
                return
            raise JSError('array property %r' % key)
        if isinstance(obj, dict):
            obj[_key(key)] = v
        elif hasattr(obj, 'props'):
            obj.props[_key(key)] = v
        else:
            raise JSError('cannot set %r on %r' % (key, obj))

    def binop(self, op, a, b):
        if op == '+':
            if isinstance(a, (int, float)) and isinstance(b, (int, float)):
                return float(a) + float(b)
            if isinstance(a, (str, list, dict)) or isinstance(b, (str, list, dict)):
                return to_str(a) + to_str(b)
            return to_num(a) + to_num(b)
        if op == '===':
            return strict_eq(a, b)
        if op == '!==':
            return not strict_eq(a, b)
        if op == '==':
            return loose_eq(a, b)
        if op == '!=':
            return not loose_eq(a, b)
        if op in ('<', '>', '<=', '>='):
            if isinstance(a, str) and isinstance(b, str):
                x, y = a, b
            else:
                x, y = to_num(a), to_num(b)
                if x != x or y != y:
                    return False
            return {'<': x < y, '>': x > y, '<=': x <= y, '>=': x >= y}[op]
        if op == 'in':
            return _key(a) in b if isinstance(b, dict) else (isinstance(_idx(a), int) and _idx(a) < len(b))
        if op == 'instanceof':
            return isinstance(a, list) if getattr(b, 'name', '') == 'Array' else isinstance(a, dict)
        x, y = to_num(a), to_num(b)
        if op == '-':
            return x - y
        if op == '*':
            return x * y
        if op == '/':
            if y == 0:
                return math.nan if x == 0 or x != x else math.copysign(math.inf, x) * (1 if str(y)[0] != '-' else -1)
            return x / y
        if op == '%':
            if y == 0 or x != x or y != y or x in (math.inf, -math.inf):
                return math.nan
            return math.fmod(x, y)
        if op == '**':
            return x ** y
        if op == '&':
            return float(to_int32(x) & to_int32(y))
        if op == '|':
            return float(to_int32(x) | to_int32(y))
        if op == '^':
            return float(to_int32(x) ^ to_int32(y))
        if op == '<<':
            return float(to_int32(to_int32(x) << (to_int32(y) & 31)))
        if op == '>>':
            return float(to_int32(x) >> (to_int32(y) & 31))
        if op == '>>>':
            return float((to_int32(x) & 0xffffffff) >> (to_int32(y) & 31))
        raise JSError('operator %s' % op)

    def get_prop(self, obj, key):
        from jsbuiltins import get_prop
        return get_prop(self, obj, key)
