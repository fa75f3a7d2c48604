"""WebGL conformance shader tests (KhronosGroup/WebGL sdk/tests).

Every page that loads `js/glsl-conformance-test.js` is run: its inline scripts (and the
helper scripts it loads from the suite, other than the harness itself) go through a small
JavaScript interpreter (jsmini), with the harness replaced by Python stand-ins that record
each case handed to `GLSLConformanceTester.runTests`, `runRenderTests`, `runTest` or
`runRenderTest`. A case's fields follow the harness (`runOneTest`): default shaders,
`vShaderId`/`fShaderId` looked up in the page's `<script>` elements, `vShaderPrep`.
Cases with a `#version 300 es` shader go to the ES 3.00 file, the others to the ES 1.00 one.
Pages the interpreter cannot run are reported and left out. A body `onload` handler (or
`window.onload`) runs after the scripts, and elements with an id are globals, as in a
browser. Not produced: the browser's answers (`chromium_webgl1`, `chromium_webgl2`).
"""

import html.parser
import os
import re

import jsmini
from jsmini import JSArray, JSError, JSObject, Native, undefined, to_str

HARNESS = ('js-test-pre.js', 'webgl-test-utils.js', 'glsl-conformance-test.js', 'js-test-post.js',
           'desktop-gl-constants.js', 'webgl-test-harness.js')

DEFAULT_VS = '\n'.join(['attribute vec4 vPosition;', 'void main()', '{', '    gl_Position = vPosition;', '}'])
DEFAULT_FS = '\n'.join(['precision mediump float;', 'void main()', '{',
                        '    gl_FragColor = vec4(1.0,0.0,0.0,1.0);', '}'])
DEFAULT_VS3 = '\n'.join(['#version 300 es', 'in vec4 vPosition;', 'void main()', '{',
                         '    gl_Position = vPosition;', '}'])
DEFAULT_FS3 = '\n'.join(['#version 300 es', 'precision mediump float;', 'out vec4 my_FragColor;',
                         'void main()', '{', '    my_FragColor = vec4(1.0,0.0,0.0,1.0);', '}'])


class _Page(html.parser.HTMLParser):
    """The page's <script> elements in order: (attrs, text)."""

    def __init__(self):
        super().__init__(convert_charrefs=False)
        self.scripts = []
        self.onload = None
        self._cur = None

    def handle_starttag(self, tag, attrs):
        if tag == 'body':
            self.onload = dict(attrs).get('onload')
        if tag == 'script':
            self._cur = (dict(attrs), [])
            self.scripts.append(self._cur)

    def handle_endtag(self, tag):
        if tag == 'script':
            self._cur = None

    def handle_data(self, data):
        if self._cur is not None:
            self._cur[1].append(data)

    handle_entityref = None
    handle_charref = None


def _scripts(text):
    p = _Page()
    p.feed(text)
    p.close()
    return [(a, ''.join(parts)) for a, parts in p.scripts], p.onload


class _Element(JSObject):
    """A <script> element: its text is shared with the recorder, so pages may rewrite it."""

    TEXT = ('text', 'textContent', 'innerHTML', 'innerText')

    def __init__(self, rec, elem_id):
        super().__init__(id=elem_id)
        self.rec, self.elem_id = rec, elem_id

    def __contains__(self, k):
        return k in self.TEXT or dict.__contains__(self, k)

    def __getitem__(self, k):
        if k in self.TEXT:
            return self.rec.by_id[self.elem_id]
        return dict.__getitem__(self, k)

    def __setitem__(self, k, v):
        if k in self.TEXT:
            self.rec.by_id[self.elem_id] = to_str(v)
        else:
            dict.__setitem__(self, k, v)


def read_test_lists(base):
    """Page path -> (min version, max version) over the suite's 00_test_list.txt files."""
    out = {}

    def walk(rel, minv, maxv):
        path = os.path.join(base, rel)
        if not os.path.exists(path):
            return
        d = os.path.dirname(rel)
        for line in open(path, encoding='utf-8'):
            line = line.strip()
            if not line or line.startswith('//') or line.startswith('#'):
                continue
            parts = line.split()
            lmin, lmax = minv, maxv
            i = 0
            while parts[i].startswith('--'):
                if parts[i] == '--min-version':
                    lmin = parts[i + 1]
                    i += 2
                elif parts[i] == '--max-version':
                    lmax = parts[i + 1]
                    i += 2
                else:
                    i += 1
            name = os.path.normpath(os.path.join(d, parts[i])).replace(os.sep, '/')
            if name.endswith('.txt'):
                walk(name, None, None)  # a list's own options are not recorded on its pages
            else:
                out[name] = (lmin, lmax)

    walk('00_test_list.txt', None, None)
    return out


def _version_of(src):
    m = re.search(r'^[ \t]*#[ \t]*version[ \t]+(\d+(?:[ \t]+es)?)', src, re.M) if isinstance(src, str) else None
    return re.sub(r'\s+', ' ', m.group(1)) if m else '100'


def _vtuple(v):
    return tuple(int(x) for x in v.split('.'))


class _Recorder:
    def __init__(self, interp, scripts):
        self.interp = interp
        self.cases = []
        self.by_id = {a.get('id'): t for a, t in scripts if a.get('id')}
        self.description = ''

    def element_text(self, elem_id):
        if elem_id not in self.by_id:
            raise JSError('no element %r' % elem_id)
        return self.by_id[elem_id]

    def record(self, api, infos, context_version):
        for i, info in enumerate(infos):
            self.cases.append((api, i, info, context_version))

    def setup_test(self):
        info = JSObject()

        def get_source(i):
            return re.sub(r'\s*$', '', re.sub(r'^\s*', '', self.by_id[i], count=1), count=1)

        def success(msg):
            if 'fail' in msg:
                return False
            if 'succeed' in msg:
                return True
            return undefined
        if 'vertexShader' in self.by_id:
            info['vShaderSource'] = get_source('vertexShader')
            info['passMsg'] = info['vShaderSource'].split('\n')[0][3:]
            info['vShaderSuccess'] = success(info['passMsg'])
        if 'fragmentShader' in self.by_id:
            info['fShaderSource'] = get_source('fragmentShader')
            info['passMsg'] = info['fShaderSource'].split('\n')[0][3:]
            info['fShaderSuccess'] = success(info['passMsg'])
        info['linkSuccess'] = info.get('vShaderSuccess') is not False and info.get('fShaderSuccess') is not False
        return info


def _anything():
    """A stand-in for browser objects the pages touch but the cases do not depend on."""
    obj = Native(lambda this, *a: _anything(), 'anything')
    obj.props['construct'] = lambda a: _anything()
    return obj


class _AnyObject(JSObject):
    def __missing__(self, key):
        return _anything()


def _fake_gl():
    gl = _AnyObject()
    consts = dict(VERTEX_SHADER=35633.0, FRAGMENT_SHADER=35632.0, COMPILE_STATUS=35713.0,
                  LINK_STATUS=35714.0, MAX_VERTEX_ATTRIBS=34921.0, MAX_VARYING_VECTORS=36348.0,
                  MAX_VERTEX_UNIFORM_VECTORS=36347.0, MAX_FRAGMENT_UNIFORM_VECTORS=36349.0,
                  MAX_TEXTURE_IMAGE_UNITS=34930.0, MAX_COMBINED_TEXTURE_IMAGE_UNITS=35661.0,
                  MAX_VERTEX_TEXTURE_IMAGE_UNITS=35660.0, MAX_DRAW_BUFFERS=34852.0,
                  MIN_PROGRAM_TEXEL_OFFSET=35076.0, MAX_PROGRAM_TEXEL_OFFSET=35077.0)
    gl.update(consts)
    limits = {36348.0: 15.0, 36347.0: 256.0, 36349.0: 224.0, 34921.0: 16.0, 34930.0: 16.0,
              35661.0: 32.0, 35660.0: 16.0, 34852.0: 8.0, 35076.0: -8.0, 35077.0: 7.0}
    gl['getParameter'] = Native(lambda this, p=undefined: limits.get(p, 0.0))
    gl['getExtension'] = Native(lambda this, *a: None)
    gl['getSupportedExtensions'] = Native(lambda this, *a: JSArray())
    gl['getShaderPrecisionFormat'] = Native(lambda this, *a: JSObject(rangeMin=127.0, rangeMax=127.0, precision=23.0))
    return gl


def _install_harness(interp, rec):
    g = interp.glob.vars
    noop = Native(lambda this, *a: undefined)
    for name in ('debug', 'testPassed', 'testFailed', 'finishTest', 'shouldBe', 'shouldBeTrue',
                 'shouldBeFalse', 'shouldBeNull', 'shouldBeUndefined', 'shouldBeNonNull', 'bufferedLogToConsole',
                 'shouldThrow', 'shouldNotThrow', 'shouldBeEqualToString', 'setTimeout', 'requestAnimationFrame',
                 'addEventListener', 'assertMsg', 'notifyFinishedToHarness', 'expectTrue'):
        g[name] = noop
    g['description'] = Native(lambda this, d='': setattr(rec, 'description', d) or undefined)
    g['successfullyParsed'] = False
    g['quietMode'] = Native(lambda this: True)
    g['gl'] = _fake_gl()
    wtu = _AnyObject()
    wtu['getScript'] = Native(lambda this, i: rec.element_text(to_str(i)))
    wtu['replaceParams'] = Native(lambda this, s, *params: _replace_params(s, params))
    wtu['create3DContext'] = Native(lambda this, *a: g['gl'])
    wtu['getWebGLContext'] = Native(lambda this, *a: g['gl'])
    wtu['glEnumToString'] = Native(lambda this, gl, v: to_str(v))
    wtu['getUrlOptions'] = Native(lambda this: JSObject())
    g['WebGLTestUtils'] = wtu
    g['wtu'] = wtu

    def runner(api):
        def run(this, tests=undefined, ctx=undefined):
            if api in ('runTest', 'runRenderTest'):
                info = rec.setup_test()
                if api == 'runRenderTest':
                    info['render'] = True
                rec.record(api, [info], None)
            else:
                if api == 'runRenderTests':
                    for t in tests:
                        t['render'] = True
                rec.record(api, list(tests), None if ctx is undefined else ctx)
            return undefined
        return Native(run, api)
    g['GLSLConformanceTester'] = JSObject({a: runner(a) for a in ('runTests', 'runRenderTests', 'runTest', 'runRenderTest')})
    doc = _AnyObject()
    elements = {i: _Element(rec, i) for i in rec.by_id}
    doc['getElementById'] = Native(lambda this, i: elements.get(to_str(i), None))
    g['document'] = doc
    for i, el in elements.items():
        if re.match(r'^[A-Za-z_$][\w$]*$', i) and i not in g:
            g[i] = el  # browsers expose elements with an id as globals
    g['window'] = _AnyObject()
    g['navigator'] = _AnyObject(userAgent='')


def _replace_params(s, params):
    def sub(m):
        for p in params:
            if isinstance(p, dict) and p.get(m.group(1), undefined) is not undefined:
                return to_str(p[m.group(1)])
        raise JSError("unknown string param '%s'" % m.group(1))
    return re.sub(r'\$\((\w+)\)', sub, s)


def _value(v):
    """A JS value as the browser's JSON.stringify writes it."""
    if v is undefined:
        return None
    if isinstance(v, float):
        return int(v) if v.is_integer() else v
    if isinstance(v, list):
        return [_value(x) for x in v]
    if isinstance(v, dict):
        return {k: _value(x) for k, x in v.items() if x is not undefined}
    return v


def _opt_bool(info, key):
    v = info.get(key, undefined)
    if v is undefined:
        return None
    return bool(jsmini.truthy(v)) if not isinstance(v, bool) else v


def case_record(rel, api, index, info, ctx, lists):
    vs, fs = info.get('vShaderSource', undefined), info.get('fShaderSource', undefined)
    vid, fid = info.get('vShaderId', undefined), info.get('fShaderId', undefined)
    v_default = f_default = False
    exp_v, exp_f = _opt_bool(info, 'vShaderSuccess'), _opt_bool(info, 'fShaderSuccess')
    if vs is undefined:
        if jsmini.truthy(vid):
            vs = info['_by_id'](vid)
        else:
            v_default = True
    if fs is undefined:
        if jsmini.truthy(fid):
            fs = info['_by_id'](fid)
        else:
            f_default = True
    if v_default:
        vs, exp_v = DEFAULT_VS, True
    if f_default:
        fs, exp_f = DEFAULT_FS, True
    if v_default != f_default:
        if f_default and vs.split('\n')[0] == '#version 300 es':
            fs = DEFAULT_FS3
        elif v_default and fs.split('\n')[0] == '#version 300 es':
            vs = DEFAULT_VS3
    prep = info.get('vShaderPrep', undefined)
    if prep is not undefined:
        vs = info['_call'](prep, vs)
    prep = info.get('fShaderPrep', undefined)
    if prep is not undefined:
        fs = info['_call'](prep, fs)
    link = _opt_bool(info, 'linkSuccess')
    listed = lists.get(rel)
    minv, maxv = listed if listed else (None, None)
    ignore = bool(jsmini.truthy(info.get('ignoreResults', undefined)))
    must_fail = exp_v is False or exp_f is False or link is False
    rec = {
        'file': rel, 'index': index, 'api': api, 'context_version': _value(ctx),
        'vertex_source': vs, 'fragment_source': fs,
        'vertex_is_default': v_default, 'fragment_is_default': f_default,
        'vertex_id': _value(vid) if jsmini.truthy(vid) else None,
        'fragment_id': _value(fid) if jsmini.truthy(fid) else None,
        'expect_vertex_compile': exp_v, 'expect_fragment_compile': exp_f, 'expect_link': link,
        'message': _value(info.get('passMsg', undefined)),
        'render': bool(jsmini.truthy(info.get('render', undefined))),
        'render_color': _value(info.get('renderColor', undefined)),
        'ignore_results': ignore,
        'has_custom_shader_test': info.get('vShaderTest', undefined) is not undefined
        or info.get('fShaderTest', undefined) is not undefined,
    }
    if info.get('uniforms', undefined) is not undefined:
        rec['uniforms'] = _value(info['uniforms'])
    if info.get('uniformBlocks', undefined) is not undefined:
        rec['has_uniform_blocks'] = True
    rec.update({
        'in_test_list': listed is not None, 'min_webgl_version': minv, 'max_webgl_version': maxv,
        'applies_to_webgl2': maxv is None or _vtuple(maxv) >= (2, 0, 0),
        'vertex_version': _version_of(vs), 'fragment_version': _version_of(fs),
        'must_fail': must_fail, 'outcome': 'any' if ignore else ('must_fail' if must_fail else 'must_pass'),
    })
    return rec


def run_page(base, rel):
    path = os.path.join(base, rel)
    with open(path, encoding='utf-8', newline='') as f:
        text = f.read()
    scripts, onload = _scripts(text)
    interp = jsmini.Interpreter()
    rec = _Recorder(interp, scripts)
    _install_harness(interp, rec)
    for attrs, body in scripts:
        typ = (attrs.get('type') or 'text/javascript').strip().lower()
        if typ not in ('text/javascript', 'application/javascript', 'module'):
            continue
        src = attrs.get('src')
        if src:
            if os.path.basename(src) in HARNESS:
                continue
            spath = os.path.normpath(os.path.join(os.path.dirname(path), src))
            with open(spath, encoding='utf-8') as f:
                body = f.read()
        interp.run(body)
    handler = interp.glob.vars['window'].get('onload') if 'onload' in dict.keys(interp.glob.vars['window']) else None
    if onload:
        interp.run(onload)
    elif handler is not None:
        interp.call(handler, undefined, [])
    out = []
    for api, index, info, ctx in rec.cases:
        info = JSObject(info)
        info['_by_id'] = lambda i: rec.element_text(to_str(i))
        info['_call'] = lambda fn, s: interp.call(fn, undefined, [s])
        out.append((api, index, info, ctx))
    return out


def candidate_pages(base):
    pages = []
    for top in ('conformance', 'conformance2', 'extra'):
        for d, _, files in os.walk(os.path.join(base, top)):
            for fn in files:
                if fn.endswith('.html'):
                    p = os.path.join(d, fn)
                    with open(p, encoding='utf-8', errors='replace') as f:
                        if 'glsl-conformance-test.js' in f.read():
                            pages.append(os.path.relpath(p, base).replace(os.sep, '/'))
    return sorted(pages)


def extract(webgl_root, skip_pages=()):
    base = os.path.join(webgl_root, 'sdk', 'tests')
    lists = read_test_lists(base)
    es300, es100, problems = [], [], []
    for rel in candidate_pages(base):
        if rel in skip_pages:
            continue
        try:
            cases = run_page(base, rel)
            recs = [case_record(rel, *c, lists=lists) for c in cases]
        except (JSError, jsmini.JSThrow, RecursionError, KeyError, IndexError, TypeError, ValueError,
                AttributeError, OSError) as ex:
            problems.append((rel, '%s: %s' % (type(ex).__name__, str(ex)[:200])))
            continue
        for r in recs:
            (es300 if '300 es' in (r['vertex_version'], r['fragment_version']) else es100).append(r)
    return es300, es100, problems
