"""TOML for the package: a scene given as a dict, written as TOML text for the library's one scene loader,
and `loads`, the standard library's reader (tomllib, Python 3.11+; tomli, the same code, before).

Only what scenes use: tables, arrays of tables (species), strings, booleans, integers, floats (repr is
the shortest text that reads back to the same double), and arrays of these. Python has tomllib to read
TOML but nothing to write it; this writer is small enough to own.
"""
import math
import numbers

try:
    from tomllib import loads
except ImportError:  # Python < 3.11 (pyproject.toml requires tomli there)
    from tomli import loads

__all__ = ["dumps", "loads", "value_text"]


def _key(k):
    k = str(k)
    if k and all(c.isalnum() or c in "-_" for c in k):
        return k
    return _string(k)


def _string(s):
    out = ['"']
    for c in s:
        if c == '"' or c == "\\":
            out.append("\\" + c)
        elif ord(c) < 0x20 or ord(c) == 0x7F:
            out.append("\\u%04x" % ord(c))
        else:
            out.append(c)
    out.append('"')
    return "".join(out)


def value_text(v):
    """One TOML value (what --set and `set=` take)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        f = float(v)
        if math.isnan(f):
            return "nan"
        if math.isinf(f):
            return "inf" if f > 0 else "-inf"
        text = repr(f)
        return text if any(c in text for c in ".en") else text + ".0"
    if isinstance(v, str):
        return _string(v)
    if hasattr(v, "tolist"):  # numpy arrays and scalars
        return value_text(v.tolist())
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(value_text(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(_key(k) + " = " + value_text(x) for k, x in v.items()) + "}"
    raise TypeError("scene value: expected a number, string, bool, list or dict, got %s" % type(v).__name__)


def _is_table_array(v):
    return isinstance(v, (list, tuple)) and len(v) > 0 and all(isinstance(x, dict) for x in v)


def _table(lines, path, table):
    plain = [(k, v) for k, v in table.items() if not isinstance(v, dict) and not _is_table_array(v)]
    for k, v in plain:
        lines.append("%s = %s" % (_key(k), value_text(v)))
    for k, v in table.items():
        name = path + [_key(k)]
        if isinstance(v, dict):
            lines.append("")
            lines.append("[%s]" % ".".join(name))
            _table(lines, name, v)
        elif _is_table_array(v):
            for item in v:
                lines.append("")
                lines.append("[[%s]]" % ".".join(name))
                _table(lines, name, item)


def dumps(scene):
    """The TOML text of a scene dict."""
    if not isinstance(scene, dict):
        raise TypeError("scene: expected a dict, got %s" % type(scene).__name__)
    lines = []
    _table(lines, [], scene)
    return "\n".join(lines) + "\n"
