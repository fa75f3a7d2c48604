"""Built-in objects and methods for jsmini (strings, arrays, Math, JSON, Object)."""

import json
import math
import re

from jsmini import (JSArray, JSError, JSFunction, JSObject, JSRegExp, Native, _idx, _key, _num_to_str,
                    strict_eq, to_int32, to_num, to_str, truthy, undefined)


def _n(fn):
    return Native(fn)


def _js_replacement(template, m):
    out, i = [], 0
    while i < len(template):
        c = template[i]
        if c == '$' and i + 1 < len(template):
            d = template[i + 1]
            if d == '$':
                out.append('$')
                i += 2
                continue
            if d == '&':
                out.append(m.group(0))
                i += 2
                continue
            if d.isdigit():
                g = int(d)
                if i + 2 < len(template) and template[i + 2].isdigit() and int(template[i + 1:i + 3]) <= (m.re.groups):
                    g = int(template[i + 1:i + 3])
                    i += 1
                if 0 < g <= m.re.groups:
                    out.append(m.group(g) or '')
                    i += 2
                    continue
        out.append(c)
        i += 1
    return ''.join(out)


def _replace(interp, s, pat, rep, all_=False):
    def sub(m):
        if isinstance(rep, (JSFunction, Native)):
            args = [m.group(0)] + [g if g is not None else undefined for g in m.groups()] + [float(m.start()), s]
            return to_str(interp.call(rep, undefined, args))
        return _js_replacement(to_str(rep), m)
    if isinstance(pat, JSRegExp):
        return pat.re.sub(sub, s, count=0 if pat.glob else 1)
    return re.compile(re.escape(to_str(pat))).sub(sub, s, count=0 if all_ else 1)


def _split(s, sep, limit=undefined):
    if sep is undefined:
        r = [s]
    elif isinstance(sep, JSRegExp):
        r = sep.re.split(s) if sep.source else list(s)
    elif sep == '':
        r = list(s)
    else:
        r = s.split(sep)
    if limit is not undefined:
        r = r[:int(to_num(limit))]
    return JSArray(r)


def _substring(s, a, b=undefined):
    n = len(s)
    a = 0 if a is undefined else min(max(int(to_num(a)) if to_num(a) == to_num(a) else 0, 0), n)
    b = n if b is undefined else min(max(int(to_num(b)) if to_num(b) == to_num(b) else 0, 0), n)
    return s[min(a, b):max(a, b)]


def _rel(i, n, default):
    if i is undefined:
        return default
    i = int(to_num(i))
    return max(n + i, 0) if i < 0 else min(i, n)


def string_method(interp, s, name):
    m = {
        'split': lambda this, sep=undefined, lim=undefined: _split(s, sep, lim),
        'replace': lambda this, p, r: _replace(interp, s, p, r),
        'replaceAll': lambda this, p, r: _replace(interp, s, p, r, True),
        'indexOf': lambda this, x, i=0.0: float(s.find(to_str(x), int(to_num(i)))),
        'lastIndexOf': lambda this, x: float(s.rfind(to_str(x))),
        'includes': lambda this, x: to_str(x) in s,
        'startsWith': lambda this, x: s.startswith(to_str(x)),
        'endsWith': lambda this, x: s.endswith(to_str(x)),
        'substring': lambda this, a=undefined, b=undefined: _substring(s, a, b),
        'substr': lambda this, a, n=undefined: s[_rel(a, len(s), 0):][:len(s) if n is undefined else max(int(to_num(n)), 0)],
        'slice': lambda this, a=undefined, b=undefined: s[_rel(a, len(s), 0):_rel(b, len(s), len(s))],
        'charAt': lambda this, i=0.0: s[int(to_num(i))] if 0 <= int(to_num(i)) < len(s) else '',
        'charCodeAt': lambda this, i=0.0: float(ord(s[int(to_num(i))])) if 0 <= int(to_num(i)) < len(s) else math.nan,
        'toUpperCase': lambda this: s.upper(),
        'toLowerCase': lambda this: s.lower(),
        'trim': lambda this: s.strip(' \t\n\r\v\f\xa0\ufeff'),
        'trimStart': lambda this: s.lstrip(),
        'trimEnd': lambda this: s.rstrip(),
        'repeat': lambda this, n: s * int(to_num(n)),
        'concat': lambda this, *a: s + ''.join(to_str(x) for x in a),
        'padStart': lambda this, n, p=' ': s.rjust(int(to_num(n)), to_str(p)[:1] or ' '),
        'padEnd': lambda this, n, p=' ': s.ljust(int(to_num(n)), to_str(p)[:1] or ' '),
        'toString': lambda this: s,
        'match': lambda this, r: _match(s, r),
        'search': lambda this, r: float(r.re.search(s).start()) if r.re.search(s) else -1.0,
    }.get(name)
    if m is None:
        raise JSError('string method %s' % name)
    return Native(m, name)


def _match(s, r):
    if not isinstance(r, JSRegExp):
        r = JSRegExp(re.escape(to_str(r)), '')
    if r.glob:
        found = [m.group(0) for m in r.re.finditer(s)]
        return JSArray(found) if found else None
    m = r.re.search(s)
    if not m:
        return None
    arr = JSArray([m.group(0)] + [g if g is not None else undefined for g in m.groups()])
    return arr


def _sort(interp, arr, cmp=undefined):
    import functools
    if cmp is undefined:
        arr.sort(key=to_str)
    else:
        arr.sort(key=functools.cmp_to_key(lambda a, b: int(math.copysign(1, v) if (v := to_num(interp.call(cmp, undefined, [a, b]))) else 0)))
    return arr


def array_method(interp, a, name):
    call = interp.call

    def cb(f, *args):
        return call(f, undefined, list(args))
    m = {
        'push': lambda this, *x: (a.extend(x), float(len(a)))[1],
        'pop': lambda this: a.pop() if a else undefined,
        'shift': lambda this: a.pop(0) if a else undefined,
        'unshift': lambda this, *x: (a.__setitem__(slice(0, 0), x), float(len(a)))[1],
        'concat': lambda this, *xs: JSArray(a + [y for x in xs for y in (x if isinstance(x, list) else [x])]),
        'join': lambda this, sep=',': (to_str(sep) if sep is not undefined else ',').join('' if x is None or x is undefined else to_str(x) for x in a),
        'slice': lambda this, s=undefined, e=undefined: JSArray(a[_rel(s, len(a), 0):_rel(e, len(a), len(a))]),
        'splice': lambda this, s, n=undefined, *items: _splice(a, s, n, items),
        'map': lambda this, f: JSArray(cb(f, x, float(i), a) for i, x in enumerate(list(a))),
        'forEach': lambda this, f: [cb(f, x, float(i), a) for i, x in enumerate(list(a))] and undefined,
        'filter': lambda this, f: JSArray(x for i, x in enumerate(list(a)) if truthy(cb(f, x, float(i), a))),
        'some': lambda this, f: any(truthy(cb(f, x, float(i), a)) for i, x in enumerate(list(a))),
        'every': lambda this, f: all(truthy(cb(f, x, float(i), a)) for i, x in enumerate(list(a))),
        'find': lambda this, f: next((x for i, x in enumerate(list(a)) if truthy(cb(f, x, float(i), a))), undefined),
        'findIndex': lambda this, f: float(next((i for i, x in enumerate(list(a)) if truthy(cb(f, x, float(i), a))), -1)),
        'indexOf': lambda this, v: float(next((i for i, x in enumerate(a) if strict_eq(x, v)), -1)),
        'includes': lambda this, v: any(strict_eq(x, v) for x in a),
        'reduce': lambda this, f, *init: _reduce(cb, a, f, init),
        'reverse': lambda this: (a.reverse(), a)[1],
        'sort': lambda this, f=undefined: _sort(interp, a, f),
        'fill': lambda this, v, s=undefined, e=undefined: (a.__setitem__(slice(_rel(s, len(a), 0), _rel(e, len(a), len(a))), [v] * (_rel(e, len(a), len(a)) - _rel(s, len(a), 0))), a)[1],
        'flat': lambda this: JSArray(y for x in a for y in (x if isinstance(x, list) else [x])),
        'keys': lambda this: JSArray(float(i) for i in range(len(a))),
        'entries': lambda this: JSArray(JSArray([float(i), x]) for i, x in enumerate(a)),
        'toString': lambda this: to_str(a),
    }.get(name)
    if m is None:
        raise JSError('array method %s' % name)
    return Native(m, name)


def _splice(a, s, n, items):
    s = _rel(s, len(a), 0)
    n = len(a) - s if n is undefined else max(int(to_num(n)), 0)
    removed = JSArray(a[s:s + n])
    a[s:s + n] = list(items)
    return removed


def _reduce(cb, a, f, init):
    items = list(a)
    acc = init[0] if init else items.pop(0)
    start = 0 if init else 1
    for i, x in enumerate(items):
        acc = cb(f, acc, x, float(i + start), a)
    return acc


def get_prop(interp, obj, key):
    if isinstance(obj, str):
        if key == 'length':
            return float(len(obj))
        i = _idx(key)
        if isinstance(i, int):
            return obj[i] if i < len(obj) else undefined
        return string_method(interp, obj, key)
    if isinstance(obj, list):
        if key == 'length':
            return float(len(obj))
        i = _idx(key)
        if isinstance(i, int):
            return obj[i] if 0 <= i < len(obj) else undefined
        return array_method(interp, obj, key)
    if isinstance(obj, dict):
        k = _key(key)
        if k in obj:
            return obj[k]
        if hasattr(obj, '__missing__'):
            return obj[k]
        if k == 'hasOwnProperty':
            return Native(lambda this, p: _key(p) in obj)
        if k == 'toString':
            return Native(lambda this: '[object Object]')
        return undefined
    if isinstance(obj, bool):
        if key == 'toString':
            return Native(lambda this: to_str(obj))
    if isinstance(obj, (int, float)):
        if key == 'toFixed':
            return Native(lambda this, d=0.0: '%.*f' % (int(to_num(d)), obj))
        if key == 'toString':
            return Native(lambda this, base=undefined: _radix(obj, base))
        if key == 'toPrecision':
            return Native(lambda this, d: _to_precision(obj, int(to_num(d))))
        raise JSError('number property %s' % key)
    if isinstance(obj, (JSFunction, Native)):
        k = _key(key)
        if k in obj.props:
            return obj.props[k]
        if k == 'call':
            return Native(lambda this, t=undefined, *a: interp.call(obj, t, list(a)))
        if k == 'apply':
            return Native(lambda this, t=undefined, a=JSArray(): interp.call(obj, t, list(a) if isinstance(a, list) else []))
        if k == 'bind':
            return Native(lambda this, t=undefined, *a: Native(lambda th, *b: interp.call(obj, t, list(a) + list(b))))
        if k == 'prototype':
            obj.props['prototype'] = JSObject()
            return obj.props['prototype']
        if k == 'name':
            return obj.name or ''
        return undefined
    if isinstance(obj, JSRegExp):
        if key == 'test':
            return Native(lambda this, s: obj.re.search(to_str(s)) is not None)
        if key == 'exec':
            return Native(lambda this, s: _match(to_str(s), JSRegExp(obj.source, obj.flags.replace('g', ''))))
        if key == 'source':
            return obj.source
        raise JSError('regexp property %s' % key)
    if obj is undefined or obj is None:
        raise JSError('cannot read %r of %s' % (key, to_str(obj)))
    raise JSError('property %r of %r' % (key, type(obj)))


def _radix(x, base):
    if base is undefined or int(to_num(base)) == 10:
        return _num_to_str(x)
    b = int(to_num(base))
    n = int(x)
    digits = '0123456789abcdefghijklmnopqrstuvwxyz'
    if n == 0:
        return '0'
    neg, n = n < 0, abs(n)
    out = ''
    while n:
        out = digits[n % b] + out
        n //= b
    return ('-' if neg else '') + out


def _to_precision(x, d):
    s = '%.*g' % (d, x)
    if 'e' not in s and '.' not in s and len(s.lstrip('-')) < d:
        s += '.' + '0' * (d - len(s.lstrip('-')))
    return s


def _json(v):
    if v is undefined:
        return None
    if isinstance(v, float) and v.is_integer():
        return int(v)
    if isinstance(v, list):
        return [_json(x) for x in v]
    if isinstance(v, dict):
        return {k: _json(x) for k, x in v.items() if x is not undefined and not isinstance(x, (JSFunction, Native))}
    return v


def _parse_int(s, base=undefined):
    s = to_str(s).strip()
    b = 10 if base is undefined or to_num(base) == 0 else int(to_num(base))
    m = re.match(r'[+-]?0[xX][0-9a-fA-F]+' if b == 16 and s[:2].lower() in ('0x', '-0', '+0') else r'[+-]?[0-9a-zA-Z]+', s)
    if not m:
        return math.nan
    t = m.group(0)
    digits = ''
    sign = -1 if t.startswith('-') else 1
    t = t.lstrip('+-')
    if b == 16 and t[:2].lower() == '0x':
        t = t[2:]
    for ch in t:
        try:
            if int(ch, 36) >= b:
                break
        except ValueError:
            break
        digits += ch
    return float(sign * int(digits, b)) if digits else math.nan


def _parse_float(s):
    m = re.match(r'\s*[+-]?(Infinity|\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)', to_str(s))
    return float(m.group(0).replace('Infinity', 'inf')) if m else math.nan


def install(interp):
    g = interp.glob.vars
    math_obj = JSObject(
        PI=math.pi, E=math.e, SQRT2=math.sqrt(2), LN2=math.log(2),
        floor=_n(lambda t, x: float(math.floor(to_num(x)))), ceil=_n(lambda t, x: float(math.ceil(to_num(x)))),
        round=_n(lambda t, x: float(math.floor(to_num(x) + 0.5))), abs=_n(lambda t, x: abs(to_num(x))),
        min=_n(lambda t, *a: min((to_num(x) for x in a), default=math.inf)),
        max=_n(lambda t, *a: max((to_num(x) for x in a), default=-math.inf)),
        pow=_n(lambda t, a, b: to_num(a) ** to_num(b)), sqrt=_n(lambda t, x: math.sqrt(to_num(x))),
        sin=_n(lambda t, x: math.sin(to_num(x))), cos=_n(lambda t, x: math.cos(to_num(x))),
        tan=_n(lambda t, x: math.tan(to_num(x))), atan=_n(lambda t, x: math.atan(to_num(x))),
        log=_n(lambda t, x: math.log(to_num(x)) if to_num(x) > 0 else -math.inf),
        log2=_n(lambda t, x: math.log2(to_num(x))), exp=_n(lambda t, x: math.exp(to_num(x))),
        trunc=_n(lambda t, x: float(math.trunc(to_num(x)))), sign=_n(lambda t, x: float((to_num(x) > 0) - (to_num(x) < 0))),
        fround=_n(lambda t, x: __import__('struct').unpack('f', __import__('struct').pack('f', to_num(x)))[0]),
        random=_n(lambda t: 0.5),
    )
    g['Math'] = math_obj
    g['JSON'] = JSObject(stringify=_n(lambda t, v, *a: json.dumps(_json(v), separators=(',', ':'))),
                         parse=_n(lambda t, s: _from_json(json.loads(s))))
    obj = _n(lambda t, v=undefined: JSObject() if v in (undefined, None) else v)
    obj.props.update(
        keys=_n(lambda t, o: JSArray(o.keys() if isinstance(o, dict) else [str(i) for i in range(len(o))])),
        values=_n(lambda t, o: JSArray(o.values())),
        entries=_n(lambda t, o: JSArray(JSArray([k, v]) for k, v in o.items())),
        assign=_n(lambda t, o, *srcs: ([o.update(s) for s in srcs if isinstance(s, dict)], o)[1]),
        freeze=_n(lambda t, o: o), create=_n(lambda t, p=None: JSObject(p or {})),
        defineProperty=_n(lambda t, o, k, d: o),
    )
    g['Object'] = obj
    arr = Native(lambda t, *a: JSArray([undefined] * int(to_num(a[0]))) if len(a) == 1 and isinstance(a[0], float) else JSArray(a), 'Array')
    arr.props['construct'] = lambda a: JSArray([undefined] * int(to_num(a[0]))) if len(a) == 1 and isinstance(a[0], float) else JSArray(a)
    arr.props.update(isArray=_n(lambda t, x: isinstance(x, list)), prototype=JSObject())
    arr.props['from'] = _n(lambda t, x, f=undefined: JSArray(
        (interp.call(f, undefined, [v, float(i)]) if f is not undefined else v)
        for i, v in enumerate(x if isinstance(x, (list, str)) else [undefined] * int(to_num(x.get('length', 0.0))))))
    g['Array'] = arr
    for typed in ('Float32Array', 'Uint8Array', 'Int32Array', 'Uint16Array', 'Uint32Array', 'Int8Array', 'Int16Array'):
        t = Native(lambda th, *a: undefined, typed)
        t.props['construct'] = lambda a: JSArray([0.0] * int(to_num(a[0]))) if a and isinstance(a[0], float) else JSArray(a[0] if a else [])
        g[typed] = t
    s = _n(lambda t, v='': to_str(v))
    s.props['fromCharCode'] = _n(lambda t, *c: ''.join(chr(int(to_num(x))) for x in c))
    s.props['fromCodePoint'] = s.props['fromCharCode']
    s.props['construct'] = lambda a: to_str(a[0]) if a else ''
    g['String'] = s
    num = _n(lambda t, v=0.0: to_num(v))
    num.props.update(isInteger=_n(lambda t, v: isinstance(v, float) and v.is_integer()),
                     MAX_SAFE_INTEGER=float(2 ** 53 - 1), EPSILON=2.0 ** -52, MAX_VALUE=1.7976931348623157e308)
    g['Number'] = num
    g['Boolean'] = _n(lambda t, v=False: truthy(v))
    g['parseInt'] = _n(lambda t, s, b=undefined: _parse_int(s, b))
    g['parseFloat'] = _n(lambda t, s: _parse_float(s))
    g['isNaN'] = _n(lambda t, v: to_num(v) != to_num(v))
    g['isFinite'] = _n(lambda t, v: math.isfinite(to_num(v)))
    g['NaN'] = math.nan
    g['Infinity'] = math.inf
    err = Native(lambda t, m='': JSObject(message=m), 'Error')
    err.props['construct'] = lambda a: JSObject(message=a[0] if a else '')
    g['Error'] = err
    g['RegExp'] = Native(lambda t, s, f='': JSRegExp(to_str(s), to_str(f)), 'RegExp')
    g['RegExp'].props['construct'] = lambda a: JSRegExp(to_str(a[0]), to_str(a[1]) if len(a) > 1 else '')
    quiet = _n(lambda t, *a: undefined)
    g['console'] = JSObject({'log': quiet, 'error': quiet, 'warn': quiet, 'assert': quiet})


def _from_json(v):
    if isinstance(v, list):
        return JSArray(_from_json(x) for x in v)
    if isinstance(v, dict):
        return JSObject({k: _from_json(x) for k, x in v.items()})
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return float(v)
    return v
