"""dEQP GLES3 shader library cases, as the WebGL2 conformance runner builds them.

Reads `sdk/tests/deqp/data/gles3/shaders/*.test` of a KhronosGroup/WebGL checkout and
produces one record per test case, with the shader sources specialised the way
`modules/shared/glsShaderLibrary.js` (parser) and `glsShaderLibraryCase.js` (template
filling) do in the browser: `${DECLARATIONS}`, `${SETUP}`, `${OUTPUT}` … are replaced and
the generated partner shader of a `both` case is added.
"""

import os
import re

# GLSL type name -> (scalar type, scalar count, float type of the same shape)
TYPES = {}
for _n, _k in (('float', 1), ('vec2', 2), ('vec3', 3), ('vec4', 4)):
    TYPES[_n] = ('float', _k, _n)
for _c in (2, 3, 4):
    for _r in (2, 3, 4):
        _n = 'mat%d' % _c if _c == _r else 'mat%dx%d' % (_c, _r)
        TYPES[_n] = ('float', _c * _r, _n)
for _p, _s in (('i', 'int'), ('u', 'uint'), ('b', 'bool')):
    TYPES[_s] = (_s, 1, 'float')
    for _k in (2, 3, 4):
        TYPES['%svec%d' % (_p, _k)] = (_s, _k, 'vec%d' % _k)

KEYWORDS = {'true', 'false', 'desc', 'expect', 'group', 'case', 'end', 'values', 'both',
            'vertex', 'fragment', 'uniform', 'input', 'output', 'version'}

EXPECT = {'pass': 'pass', 'compile_fail': 'compile_fail', 'link_fail': 'link_fail',
          'compile_or_link_fail': 'compile_link_fail', 'build_successful': 'build_successful'}

VERSIONS = {(100, 'es'): '100', (300, 'es'): '300 es', (310, 'es'): '310 es'}
for _v in (130, 140, 150, 330, 400, 410, 420, 430, 440, 450):
    VERSIONS[(_v, '')] = str(_v)


class ParseError(Exception):
    pass


def _is_ws(c):
    return c in ' \t\r\n' and c != ''


def _unescape(s):
    out = []
    i = 0
    while i < len(s):
        if s[i] == '\\':
            if i + 1 < len(s):
                n = s[i + 1]
                out.append({'n': '\n', 't': '\t'}.get(n, n))
            i += 2
        else:
            out.append(s[i])
            i += 1
    return ''.join(out)


def _string_literal(tok, end, trim_front=False):
    """glsShaderLibrary.parseStringLiteralHelper."""
    idx = 0
    while True:
        idx = tok.find(end, idx + 1)
        if not (idx >= 0 and tok[idx - 1] == '\\'):
            break
    if idx <= 0:
        idx = len(tok)
    s = tok[len(end):idx]
    if trim_front:
        s = re.sub(r'^\s*\n', '', s, count=1)
    return _unescape(s)


def _remove_extra_indentation(s):
    lines = re.split(r'\r\n|\r|\n', s)
    indent = 0
    for c in lines[0]:
        if not _is_ws(c):
            break
        indent += 4 if c == '\t' else 1
    out = []
    for line in lines:
        removed = 0
        j = 0
        while removed < indent and j < len(line) and _is_ws(line[j]):
            removed += 4 if line[j] == '\t' else 1
            j += 1
        out.append(line[j:])
    return '\n'.join(out)


class Parser:
    """A port of glsShaderLibrary.Parser: tokens are (kind, text)."""

    def __init__(self, text):
        self.s = text
        self.pos = 0
        self.tok = ('invalid', '')
        self.advance()

    def _scan(self):
        s, p = self.s, self.pos
        n = len(s)
        while True:
            while p < n and _is_ws(s[p]):
                p += 1
            if p < n and s[p] == '#':
                while p < n and s[p] not in '\r\n':
                    p += 1
            else:
                break
        self.pos = p
        if p >= n:
            return ('eof', '<EOF>')
        c = s[p]
        if c.isascii() and c.isalpha():
            e = p + 1
            while e < n and (s[e].isascii() and (s[e].isalnum() or s[e] in '_-.')):
                e += 1
            word = s[p:e]
            if word in KEYWORDS:
                return (word, word)
            if word in TYPES:
                return ('type', word)
            return ('ident', word)
        if c.isascii() and c.isdigit():
            e = p
            while e < n and s[e].isdigit():
                e += 1
            if e < n and s[e] == '.':
                e += 1
                while e < n and s[e].isdigit():
                    e += 1
                if e < n and s[e] in 'eE':
                    e += 1
                    if e < n and s[e] in '+-':
                        e += 1
                    while e < n and s[e].isdigit():
                        e += 1
                return ('float', s[p:e])
            return ('int', s[p:e])
        if s.startswith('""', p):
            e = p + 2
            while not s.startswith('""', e):
                if e >= n:
                    raise ParseError('unterminated shader source')
                e += 2 if s[e] == '\\' else 1
            return ('source', s[p:e + 2])
        if c in '"\'':
            e = p + 1
            while s[e] != c:
                e += 2 if s[e] == '\\' else 1
            return ('string', s[p:e + 1])
        return ('sym', c)

    def advance(self, expect=None):
        if expect is not None:
            self.assume(expect)
        self.pos += len(self.tok[1])
        self.tok = self._scan()

    def assume(self, kind, text=None):
        if self.tok[0] != kind or (text is not None and self.tok[1] != text):
            raise ParseError('unexpected token %r at %d, expecting %s' % (self.tok[1], self.pos, kind))

    def sym(self, c):
        self.assume('sym', c)
        self.advance()

    def parse(self, prefix):
        cases = []
        while self.tok[0] != 'eof':
            if self.tok[0] == 'case':
                self.parse_case(prefix, cases)
            elif self.tok[0] == 'group':
                self.parse_group(prefix, cases)
            else:
                raise ParseError('invalid token at main level: %r' % self.tok[1])
        return cases

    def parse_group(self, prefix, cases):
        self.advance('group')
        name = self.tok[1]
        self.advance()
        self.assume('string')
        self.advance()
        while self.tok[0] != 'end':
            if self.tok[0] == 'group':
                self.parse_group(prefix + name + '.', cases)
            elif self.tok[0] == 'case':
                self.parse_case(prefix + name + '.', cases)
            else:
                raise ParseError('unexpected token in group: %r' % self.tok[1])
        self.advance('end')

    def parse_value_element(self, typ, elems):
        scalar, size, _ = TYPES[typ]
        if size > 1:
            self.assume('type', typ)
            self.advance()
            self.sym('(')
        for i in range(size):
            if scalar in ('float', 'int', 'uint'):
                sign = 1
                if self.tok == ('sym', '-'):
                    sign = -1
                    self.advance()
                if scalar == 'float':
                    self.assume('float')
                    elems.append(sign * float(self.tok[1]))
                else:
                    self.assume('int')
                    elems.append(sign * int(self.tok[1], 10))
                self.advance()
            else:
                if self.tok[0] not in ('true', 'false'):
                    raise ParseError('expecting bool, got %r' % self.tok[1])
                elems.append(self.tok[0] == 'true')
                self.advance()
            if i != size - 1:
                self.sym(',')
        if size > 1:
            self.sym(')')

    def parse_value(self, block):
        storage = self.tok[0]
        self.advance()
        self.assume('type')
        typ = self.tok[1]
        self.advance()
        if self.tok[0] == 'ident':
            name = self.tok[1]
        elif self.tok[0] == 'string':
            name = _string_literal(self.tok[1], self.tok[1][0])
        else:
            raise ParseError('bad value name %r' % self.tok[1])
        self.advance()
        self.sym('=')
        value = {'storage': storage, 'name': name, 'type': typ, 'array_length': 0, 'elements': []}
        if self.tok == ('sym', '['):
            self.advance()
            while True:
                self.parse_value_element(typ, value['elements'])
                value['array_length'] += 1
                if self.tok == ('sym', ']'):
                    break
                self.sym('|')
            self.sym(']')
        else:
            self.parse_value_element(typ, value['elements'])
            value['array_length'] = 1
        self.sym(';')
        block['values'].append(value)

    def parse_value_block(self):
        block = {'array_length': 1, 'values': []}
        self.advance('values')
        self.sym('{')
        while self.tok[0] in ('uniform', 'input', 'output'):
            self.parse_value(block)
        self.sym('}')
        for v in block['values']:
            if v['array_length'] > 1:
                block['array_length'] = v['array_length']
        return block

    def parse_case(self, prefix, cases):
        self.advance('case')
        name = self.tok[1]
        self.advance()
        blocks = []
        version = '100'
        expect = 'pass'
        desc = None
        both = vert = frag = ''
        while self.tok[0] != 'end':
            kind = self.tok[0]
            if kind == 'desc':
                self.advance()
                self.assume('string')
                desc = _string_literal(self.tok[1], self.tok[1][0])
                self.advance()
            elif kind == 'expect':
                self.advance()
                self.assume('ident')
                if self.tok[1] not in EXPECT:
                    raise ParseError('invalid expected result %r' % self.tok[1])
                expect = EXPECT[self.tok[1]]
                self.advance()
            elif kind == 'values':
                blocks.append(self.parse_value_block())
            elif kind in ('both', 'vertex', 'fragment'):
                self.advance()
                self.assume('source')
                src = _remove_extra_indentation(_string_literal(self.tok[1], '""', True))
                self.advance()
                if kind == 'both':
                    both = src
                elif kind == 'vertex':
                    vert = src
                else:
                    frag = src
            elif kind == 'version':
                self.advance()
                self.assume('int')
                num = int(self.tok[1])
                self.advance()
                post = ''
                if self.tok[0] == 'ident':
                    post = self.tok[1]
                    self.advance()
                if (num, post) not in VERSIONS:
                    raise ParseError('unknown GLSL version %d %s' % (num, post))
                version = VERSIONS[(num, post)]
            else:
                raise ParseError('unexpected token in case: %r' % self.tok[1])
        self.advance('end')
        base = dict(expect=expect, version=version, description=desc, blocks=blocks)
        if both:
            cases.append(dict(base, name=prefix + name + '_vertex', case_type='vertex_only',
                              vertex=both, fragment=None))
            cases.append(dict(base, name=prefix + name + '_fragment', case_type='fragment_only',
                              vertex=None, fragment=both))
        else:
            cases.append(dict(base, name=prefix + name, case_type='complete',
                              vertex=vert, fragment=frag))


# --- template filling (glsShaderLibraryCase.js) ---

def _inout(version):
    return version not in ('100', '130', '140', '150')


def _is_float(typ):
    return TYPES[typ][0] == 'float'


def _float_type(typ):
    return TYPES[typ][2]


def gen_compare_functions(block, use_float_types):
    found = {v['type'] for v in block['values'] if v['storage'] == 'output'}
    out = []
    if use_float_types:
        table = [
            ('bool', 'bool isOk (float a, bool b) { return ((a > 0.5) == b); }'),
            ('bvec2', 'bool isOk (vec2 a, bvec2 b) { return (greaterThan(a, vec2(0.5)) == b); }'),
            ('bvec3', 'bool isOk (vec3 a, bvec3 b) { return (greaterThan(a, vec3(0.5)) == b); }'),
            ('bvec4', 'bool isOk (vec4 a, bvec4 b) { return (greaterThan(a, vec4(0.5)) == b); }'),
            ('int', 'bool isOk (float a, int b) { float atemp = a+0.5; return (float(b) <= atemp && atemp <= float(b+1)); }'),
            ('ivec2', 'bool isOk (vec2 a, ivec2 b) { return (ivec2(floor(a + 0.5)) == b); }'),
            ('ivec3', 'bool isOk (vec3 a, ivec3 b) { return (ivec3(floor(a + 0.5)) == b); }'),
            ('ivec4', 'bool isOk (vec4 a, ivec4 b) { return (ivec4(floor(a + 0.5)) == b); }'),
            ('uint', 'bool isOk (float a, uint b) { float atemp = a+0.5; return (float(b) <= atemp && atemp <= float(b+1u)); }'),
            ('uvec2', 'bool isOk (vec2 a, uvec2 b) { return (uvec2(floor(a + 0.5)) == b); }'),
            ('uvec3', 'bool isOk (vec3 a, uvec3 b) { return (uvec3(floor(a + 0.5)) == b); }'),
            ('uvec4', 'bool isOk (vec4 a, uvec4 b) { return (uvec4(floor(a + 0.5)) == b); }'),
        ]
    else:
        table = [(t, 'bool isOk (%s a, %s b) { return (a == b); }' % (t, t))
                 for t in ('bool', 'bvec2', 'bvec3', 'bvec4', 'int', 'ivec2', 'ivec3', 'ivec4',
                           'uint', 'uvec2', 'uvec3', 'uvec4')]
    for t, line in table:
        if t in found:
            out.append(line + '\n')
    for t in ('float', 'vec2', 'vec3', 'vec4'):
        if t in found:
            if t == 'float':
                out.append('bool isOk (float a, float b, float eps) { return (abs(a-b) <= (eps*abs(b) + eps)); }\n')
            else:
                out.append('bool isOk (%s a, %s b, float eps) { return all(lessThanEqual(abs(a-b), (eps*abs(b) + eps))); }\n' % (t, t))
    for t in ('mat2', 'mat2x3', 'mat2x4', 'mat3x2', 'mat3', 'mat3x4', 'mat4x2', 'mat4x3', 'mat4'):
        if t not in found:
            continue
        cols = int(t[3])
        rows = int(t[5]) if len(t) > 4 else cols
        vec = 'vec%d' % rows
        d = ['abs(a[%d]-b[%d])' % (i, i) for i in range(cols)]
        if cols == 2:
            diff = 'max(%s, %s)' % (d[0], d[1])
        elif cols == 3:
            diff = 'max(max(%s, %s), %s)' % (d[0], d[1], d[2])
        else:
            diff = 'max(max(%s, %s), max(%s, %s))' % tuple(d)
        out.append('bool isOk (%s a, %s b, float eps) { %s diff = %s; return all(lessThanEqual(diff, %s(eps))); }\n'
                   % (t, t, vec, diff, vec))
    return ''.join(out)


def gen_compare_op(dst, block, prefix):
    out = ''
    first = True
    for v in block['values']:
        if v['storage'] != 'output':
            continue
        out += 'bool RES = ' if first else 'RES = RES && '
        first = False
        if _is_float(v['type']):
            out += 'isOk(%s, ref_%s, 0.05);\n' % (v['name'], v['name'])
        else:
            out += 'isOk(%s%s, ref_%s);\n' % (prefix, v['name'], v['name'])
    if first:
        out += dst + ' = vec4(1.0);\n'
    else:
        out += dst + ' = vec4(RES, RES, RES, 1.0);\n'
    return out


def gen_vertex_shader(block, version):
    io = _inout(version)
    vin, vout = ('in', 'out') if io else ('attribute', 'varying')
    res = '#version %s\nprecision highp float;\nprecision highp int;\n\n' % version
    res += vin + ' highp vec4 dEQP_Position;\n'
    for v in block['values']:
        if v['storage'] == 'input':
            ft = _float_type(v['type'])
            res += '%s %s a_%s;\n' % (vin, ft, v['name'])
            res += '%s %s %s%s;\n' % (vout, ft, '' if _is_float(v['type']) else 'v_', v['name'])
    res += '\nvoid main()\n {\n\tgl_Position = dEQP_Position;\n'
    for v in block['values']:
        if v['storage'] == 'input':
            res += '\t%s%s = a_%s;\n' % ('' if _is_float(v['type']) else 'v_', v['name'], v['name'])
    return res + '}\n'


def gen_fragment_shader(block, version):
    io = _inout(version)
    fin = 'in' if io else 'varying'
    prec = 'mediump' if version == '100' else 'highp'
    sh = '#version %s\nprecision %s float;\nprecision %s int;\n\n' % (version, prec, prec)
    if io:
        sh += 'layout(location = 0) out mediump vec4 dEQP_FragColor;\n\n'
    sh += gen_compare_functions(block, True) + '\n'
    for v in block['values']:
        if v['storage'] == 'output':
            sh += '%s %s %s%s;\n' % (fin, _float_type(v['type']), '' if _is_float(v['type']) else 'v_', v['name'])
            sh += 'uniform %s ref_%s;\n' % (v['type'], v['name'])
    sh += '\nvoid main()\n {\n\t'
    sh += gen_compare_op('dEQP_FragColor' if io else 'gl_FragColor', block, 'v_')
    return sh + '}\n'


def _fill(src, pairs):
    for key, val in pairs:
        src = src.replace('${%s}' % key, val)
    return src


def _fill_decl(src, key, decl, rest):
    return _fill(src, [(key, decl), (key + ':single-line', decl.replace('\n', ' '))] + rest)


def specialize_vertex_shader(src, block, version):
    io = _inout(version)
    vin, vout = ('in', 'out') if io else ('attribute', 'varying')
    output = 'gl_Position = dEQP_Position;\n'
    decl = vin + ' highp vec4 dEQP_Position;\n'
    setup = ''
    for v in block['values']:
        n, t, ft = v['name'], v['type'], _float_type(v['type'])
        if v['storage'] == 'input':
            if _is_float(t):
                decl += '%s %s %s;\n' % (vin, ft, n)
            else:
                decl += '%s %s a_%s;\n' % (vin, ft, n)
                setup += '%s %s = %s(a_%s);\n' % (t, n, t, n)
        elif v['storage'] == 'output':
            if _is_float(t):
                decl += '%s %s %s;\n' % (vout, ft, n)
            else:
                decl += '%s %s v_%s;\n' % (vout, ft, n)
                decl += '%s %s;\n' % (t, n)
                output += 'v_%s = %s(%s);\n' % (n, ft, n)
    return _fill_decl(src, 'DECLARATIONS', decl,
                      [('SETUP', setup), ('OUTPUT', output), ('POSITION_FRAG_COLOR', 'gl_Position')])


def specialize_vertex_only(src, block, version):
    vin = 'in' if _inout(version) else 'attribute'
    output = 'gl_Position = dEQP_Position;\n'
    decl = vin + ' highp vec4 dEQP_Position;\n'
    setup = ''
    for v in block['values']:
        n, t = v['name'], v['type']
        if v['storage'] == 'input':
            if _is_float(t):
                decl += '%s %s %s;\n' % (vin, t, n)
            else:
                decl += '%s %s a_%s;\n' % (vin, _float_type(t), n)
                setup += '%s %s = %s(a_%s);\n' % (t, n, t, n)
        elif v['storage'] == 'uniform' and '.' not in n:
            decl += 'uniform %s %s;\n' % (t, n)
    return _fill_decl(src, 'VERTEX_DECLARATIONS', decl,
                      [('VERTEX_SETUP', setup), ('VERTEX_OUTPUT', output)])


def _int_or_ivec(t):
    return t in ('int', 'ivec2', 'ivec3', 'ivec4')


def specialize_fragment_shader(src, block, version):
    io = _inout(version)
    fin = 'in' if io else 'varying'
    color = 'dEQP_FragColor' if io else 'gl_FragColor'
    decl = gen_compare_functions(block, False)
    output = gen_compare_op(color, block, '')
    setup = ''
    if io:
        decl += 'layout(location = 0) out mediump vec4 dEQP_FragColor;\n'
    for v in block['values']:
        n, t, ft = v['name'], v['type'], _float_type(v['type'])
        if v['storage'] == 'input':
            if _is_float(t):
                decl += '%s %s %s;\n' % (fin, ft, n)
            else:
                decl += '%s %s v_%s;\n' % (fin, ft, n)
                off = ' * 1.0025' if _int_or_ivec(t) else ''
                setup += '%s %s = %s(v_%s%s);\n' % (t, n, t, n, off)
        elif v['storage'] == 'output':
            decl += 'uniform %s ref_%s;\n' % (t, n)
            decl += '%s %s;\n' % (t, n)
    return _fill_decl(src, 'DECLARATIONS', decl,
                      [('SETUP', setup), ('OUTPUT', output), ('POSITION_FRAG_COLOR', color)])


def specialize_fragment_only(src, block, version):
    io = _inout(version)
    color = 'dEQP_FragColor' if io else 'gl_FragColor'
    decl = gen_compare_functions(block, False)
    output = gen_compare_op(color, block, '')
    if io:
        decl += 'layout(location = 0) out mediump vec4 dEQP_FragColor;\n'
    for v in block['values']:
        n, t = v['name'], v['type']
        if v['storage'] == 'output':
            decl += 'uniform %s ref_%s;\n' % (t, n)
            decl += '%s %s;\n' % (t, n)
        elif v['storage'] == 'uniform' and '.' not in n:
            decl += 'uniform %s %s;\n' % (t, n)
    return _fill_decl(src, 'FRAGMENT_DECLARATIONS', decl,
                      [('FRAGMENT_OUTPUT', output), ('FRAG_COLOR', color)])


def _number(x):
    """Scalars as the browser's JSON.stringify writes them (1.0 -> 1, true -> 1)."""
    if isinstance(x, bool):
        return int(x)
    if isinstance(x, float) and x.is_integer():
        return int(x)
    return x


def case_record(rel, case):
    version = case['version']
    block = case['blocks'][0] if case['blocks'] else {'array_length': 1, 'values': []}
    if case['case_type'] == 'complete':
        vs = specialize_vertex_only(case['vertex'], block, version)
        fs = specialize_fragment_only(case['fragment'], block, version)
    elif case['case_type'] == 'vertex_only':
        vs = specialize_vertex_shader(case['vertex'], block, version)
        fs = gen_fragment_shader(block, version)
    else:
        vs = gen_vertex_shader(block, version)
        fs = specialize_fragment_shader(case['fragment'], block, version)
    # An empty `values {}` block declares nothing to check: no values then.
    has_values = any(b['values'] for b in case['blocks'])
    rec = {
        'file': rel, 'name': case['name'], 'expect': case['expect'],
        'case_type': case['case_type'], 'version': version,
        'description': case['description'], 'vertex_source': vs, 'fragment_source': fs,
        'has_values': has_values, 'requirements': 0,
    }
    if has_values:
        rec['values'] = [
            {'array_length': b['array_length'],
             'values': [dict(v, elements=[_number(e) for e in v['elements']]) for v in b['values']]}
            for b in case['blocks']]
    return rec


def extract(webgl_root, skip_files=()):
    """Yields the records of every gles3 shader .test file, in file name order."""
    base = os.path.join(webgl_root, 'sdk', 'tests')
    shaders = os.path.join(base, 'deqp', 'data', 'gles3', 'shaders')
    for fn in sorted(os.listdir(shaders)):
        if not fn.endswith('.test') or fn in skip_files:
            continue
        with open(os.path.join(shaders, fn), encoding='utf-8', newline='') as f:
            text = f.read()
        rel = 'deqp/data/gles3/shaders/' + fn
        for case in Parser(text).parse(fn[:-len('.test')] + '.'):
            yield case_record(rel, case)
