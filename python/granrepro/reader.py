"""granrepro.load: reads granrepro results (docs/schema.md) into Python with h5py + numpy
(Debian python3-h5py, python3-numpy).

A results folder is untrusted input (a downloaded paper_figures/): load() reads it without
following symlinks and within the caps of granrepro.untrusted, refuses any attribute or dataset of
another shape or type than the writer's, and verifies data.h5 against summary.json beside it:
experiment, scale, seed, every scalar and every parameter value by value, and the
content hashes of summary.json, of the scalars, of each table it reads and of /points. Anything else raises
ResultsError (ResultsMismatch where the two files disagree), one line naming the file and field."""
from __future__ import annotations

import json
import math
import os
import struct
from dataclasses import dataclass, field

import h5py
import numpy as np

from .untrusted import (MAX_POINT_FILE_BYTES, MAX_SUMMARY_BYTES, MAX_TEXT_FILE_BYTES, ResultsError, parse_json,
                        read_file, require_regular_file)

SCHEMA = "granrepro-result"
SCHEMA_VERSION = 3  # the version this reader's writer emits
# Only the current version: a schema bump regenerates paper_figures/ (docs/schema.md, "Versions").
READS_VERSIONS = (3,)
# Bytes of one dataset read at most (the cap of a point file, which /points/records is): a crafted
# dataset cannot make the reader allocate more.
MAX_DATASET_BYTES = MAX_POINT_FILE_BYTES


class ResultsMismatch(ResultsError):
    """data.h5 and summary.json beside it disagree (one of them was edited since the run)."""


class Table(dict):
    """The columns of one table, in the writer's order: name -> 1-D numpy array.
    .units: name -> unit; .description: one line; .x: name of the first column (the dimension
    scale of the others)."""

    def __init__(self, name: str, description: str = ""):
        super().__init__()
        self.name = name
        self.description = description
        self.units: dict[str, str] = {}

    @property
    def x(self) -> str:
        return next(iter(self))

    def label(self, column: str) -> str:
        """'v_y_i [m/s]': the column with its unit, for an axis label."""
        return f"{column} [{self.units.get(column, '?')}]"


@dataclass
class Quantity:
    value: object  # float, int, bool, str or numpy array
    unit: str = ""
    description: str = ""
    source: str = ""


@dataclass
class Run:
    path: str
    experiment: str
    scale: str
    seed: int
    attributes: dict
    tables: dict[str, Table] = field(default_factory=dict)
    scalars: dict[str, Quantity] = field(default_factory=dict)
    parameters: dict[str, Quantity] = field(default_factory=dict)
    claims: list[dict] = field(default_factory=list)
    provenance: dict = field(default_factory=dict)
    # Schema 3: every sweep point (data.h5 /points/records): dicts with "sweep", "point",
    # "inputs" (fingerprint), "resumed", "persisted", "cost" {cpu_s, wall_s, started_unix, part,
    # rank} and "outcome" (the point's JSON). Empty for files written before schema 3.
    points: list[dict] = field(default_factory=list)
    summary: dict = field(default_factory=dict)  # summary.json as read (verified against data.h5)

    def value(self, scalar: str) -> float:
        return self.scalars[scalar].value


# ---------------------------------------------------------------- data.h5, one object at a time


def _short(e: BaseException) -> str:
    text = str(e).splitlines()[0] if str(e) else type(e).__name__
    return text[:160]


def _variable_string(aid) -> bytes:
    """The bytes of a scalar variable-length string attribute as stored, whatever its character set
    says (decoded by the caller, which refuses what is not UTF-8); b"" for a null string."""
    out = np.empty((), dtype=h5py.string_dtype("ascii"))
    aid.read(out, mtype=h5py.h5t.py_create(out.dtype))
    v = out[()]
    return b"" if v is None else bytes(v)


class _H5:
    """data.h5 opened for reading; every read names the file and the object in its refusal."""

    def __init__(self, path: str):
        self.path = path

    def refuse(self, what: str):
        raise ResultsError(f"{self.path}: {what}; rerun the experiment to replace it")

    def attr(self, obj, where: str, name: str):
        """A scalar attribute: a UTF-8 string (fixed-length as the writer makes them, or variable-length,
        h5py's default, read as its value as the C++ readers read it), an integer or a float."""
        at = f"attribute '{name}' of {where}"
        try:
            aid = obj.attrs.get_id(name)
            shape, tid = aid.shape, aid.get_type()
            cls = tid.get_class()
        except (KeyError, OSError, ValueError, RuntimeError, TypeError) as e:
            self.refuse(f"{at} cannot be read ({_short(e)})")
        if shape != ():
            n = int(np.prod(shape)) if shape else 0
            self.refuse(f"{at} is an array of {n} values; granrepro writes one value")
        if cls == h5py.h5t.STRING:
            too_large = f"{at} is larger than its cap of {MAX_TEXT_FILE_BYTES >> 20} MiB (docs/schema.md)"
            if tid.is_variable_str():
                raw = self._read(lambda: _variable_string(aid), at)
            elif tid.get_size() > MAX_TEXT_FILE_BYTES:
                self.refuse(too_large)  # sized before it is read
            else:
                raw = self._read(lambda: obj.attrs[name], at)
            if len(raw) > MAX_TEXT_FILE_BYTES:
                self.refuse(too_large)
            try:
                return bytes(raw).decode("utf-8")
            except UnicodeDecodeError:
                self.refuse(f"{at} is not UTF-8 text")
        if cls == h5py.h5t.INTEGER:
            return int(self._read(lambda: obj.attrs[name], at))
        if cls == h5py.h5t.FLOAT:
            return float(self._read(lambda: obj.attrs[name], at))
        self.refuse(f"{at} is of another type than text or a number")

    def attrs(self, obj, where: str, skip=()) -> dict:
        return {k: self.attr(obj, where, k) for k in self.names(lambda: list(obj.attrs.keys()), where)
                if k not in skip}

    def text_attr(self, obj, where: str, name: str, default=None) -> str:
        if not self._read(lambda: name in obj.attrs, where):
            if default is None:
                self.refuse(f"{where} has no attribute '{name}'")
            return default
        v = self.attr(obj, where, name)
        if not isinstance(v, str):
            self.refuse(f"attribute '{name}' of {where} is a number; granrepro writes text")
        return v

    def group(self, parent, name: str, where: str):
        path = f"{where.rstrip('/')}/{name}"
        if not self._read(lambda: name in parent, path):
            self.refuse(f"has no {path}")
        g = self._read(lambda: parent[name], path)
        if not isinstance(g, h5py.Group):
            self.refuse(f"{path} is not a group")
        return g

    def dataset(self, g, name: str, where: str, kinds: str, ndims: tuple, what: str):
        """The values of a dataset of numeric kind in `kinds` and rank in `ndims`."""
        path = f"{where}/{name}"
        try:
            ds = g[name]
        except (KeyError, OSError, ValueError, RuntimeError) as e:
            self.refuse(f"{path} cannot be read ({_short(e)})")
        if not isinstance(ds, h5py.Dataset):
            self.refuse(f"{path} is not a dataset; {what}")
        dt, shape = ds.dtype, ds.shape
        if dt.kind not in kinds or dt.shape != () or shape is None or len(shape) not in ndims:
            found = "text" if dt.kind in "SUO" else f"{dt} of shape {shape}"
            self.refuse(f"{path} is {found}; {what}")
        if int(np.prod(shape)) * dt.itemsize > MAX_DATASET_BYTES:
            self.refuse(f"{path} is larger than the cap of {MAX_DATASET_BYTES >> 20} MiB on one dataset (docs/schema.md)")
        return ds, self._read(lambda: ds[()], path)

    def names(self, fn, where: str) -> list[str]:
        return self._read(fn, where)

    def _read(self, fn, where: str):
        try:
            return fn()
        except ResultsError:
            raise
        except (KeyError, OSError, ValueError, RuntimeError, TypeError, MemoryError) as e:
            self.refuse(f"{where} cannot be read ({_short(e)})")


def _in_creation_order(h5: _H5, group: h5py.Group, where: str) -> list[str]:
    """Link names in the order they were created (the writer tracks it, and the content hashes
    follow it); name order where the file has no creation-order index."""
    def names(order):
        out = []
        group.id.links.iterate(lambda n: out.append(n.decode("utf-8")), idx_type=order)
        return out
    try:
        return names(h5py.h5.INDEX_CRT_ORDER)
    except (KeyError, OSError, ValueError, RuntimeError):
        return h5._read(lambda: names(h5py.h5.INDEX_NAME), f"the links of {where}")


# ---------------------------------------------------------------- content hashes (docs/schema.md)

_FNV_START, _FNV_PRIME, _MASK = 14695981039346656037, 1099511628211, (1 << 64) - 1


class _ContentHash:
    """FNV-1a 64 over the bytes of src/io/result_writer.cpp's ContentHash."""

    def __init__(self):
        self.h = _FNV_START

    def bytes(self, data: bytes) -> None:
        h = self.h
        for b in data:
            h = ((h ^ b) * _FNV_PRIME) & _MASK
        self.h = h

    def text(self, s: str) -> None:
        self.bytes(s.encode("utf-8") + b"\0")

    def column(self, name: str, unit: str, values) -> None:
        v = np.asarray(values, dtype="<f8").reshape(-1)
        self.text(name)
        self.text(unit)
        self.bytes(struct.pack("<Q", v.size))
        self.bytes(v.tobytes())

    def hex(self) -> str:
        return f"fnv1a64:{self.h:016x}"


def fnv1a64(data: bytes) -> str:
    h = _ContentHash()
    h.bytes(data)
    return h.hex()


# ---------------------------------------------------------------- summary.json against data.h5

# summary_json_hash (docs/schema.md): FNV-1a 64 of summary.json as nlohmann::json's dump() writes
# it compactly: keys in byte order, no spaces, strings as json.dumps(ensure_ascii=False) writes
# them (the same escapes). Numbers are written twice over: as the file spells them (exact for
# a file the writer wrote, whose tokens are dump()'s), and as dump() writes their values (for a
# file reformatted without changing a value): _dump_float is nlohmann's to_chars (Grisu2, then
# format_buffer) ported, equal to dump() on 1.1 million doubles. Grisu2's digits are not always the
# shortest that read back (repr's): for ~0.03 % of doubles (225 of 662684 in paper_figures' /points)
# they are a digit longer or end in another digit, and a short decimal may come out long (5.66283e+20
# as 5.6628300000000003e+20). Either spelling must match.


class _Token(str):
    """A number as the file spells it."""


# (f, e, k) with f * 2^e ~= 10^k: nlohmann/detail/conversions/to_chars.hpp, kCachedPowers.
_CACHED_POWERS = (
    (0xAB70FE17C79AC6CA, -1060, -300), (0xFF77B1FCBEBCDC4F, -1034, -292), (0xBE5691EF416BD60C, -1007, -284),
    (0x8DD01FAD907FFC3C, -980, -276), (0xD3515C2831559A83, -954, -268), (0x9D71AC8FADA6C9B5, -927, -260),
    (0xEA9C227723EE8BCB, -901, -252), (0xAECC49914078536D, -874, -244), (0x823C12795DB6CE57, -847, -236),
    (0xC21094364DFB5637, -821, -228), (0x9096EA6F3848984F, -794, -220), (0xD77485CB25823AC7, -768, -212),
    (0xA086CFCD97BF97F4, -741, -204), (0xEF340A98172AACE5, -715, -196), (0xB23867FB2A35B28E, -688, -188),
    (0x84C8D4DFD2C63F3B, -661, -180), (0xC5DD44271AD3CDBA, -635, -172), (0x936B9FCEBB25C996, -608, -164),
    (0xDBAC6C247D62A584, -582, -156), (0xA3AB66580D5FDAF6, -555, -148), (0xF3E2F893DEC3F126, -529, -140),
    (0xB5B5ADA8AAFF80B8, -502, -132), (0x87625F056C7C4A8B, -475, -124), (0xC9BCFF6034C13053, -449, -116),
    (0x964E858C91BA2655, -422, -108), (0xDFF9772470297EBD, -396, -100), (0xA6DFBD9FB8E5B88F, -369, -92),
    (0xF8A95FCF88747D94, -343, -84), (0xB94470938FA89BCF, -316, -76), (0x8A08F0F8BF0F156B, -289, -68),
    (0xCDB02555653131B6, -263, -60), (0x993FE2C6D07B7FAC, -236, -52), (0xE45C10C42A2B3B06, -210, -44),
    (0xAA242499697392D3, -183, -36), (0xFD87B5F28300CA0E, -157, -28), (0xBCE5086492111AEB, -130, -20),
    (0x8CBCCC096F5088CC, -103, -12), (0xD1B71758E219652C, -77, -4), (0x9C40000000000000, -50, 4),
    (0xE8D4A51000000000, -24, 12), (0xAD78EBC5AC620000, 3, 20), (0x813F3978F8940984, 30, 28),
    (0xC097CE7BC90715B3, 56, 36), (0x8F7E32CE7BEA5C70, 83, 44), (0xD5D238A4ABE98068, 109, 52),
    (0x9F4F2726179A2245, 136, 60), (0xED63A231D4C4FB27, 162, 68), (0xB0DE65388CC8ADA8, 189, 76),
    (0x83C7088E1AAB65DB, 216, 84), (0xC45D1DF942711D9A, 242, 92), (0x924D692CA61BE758, 269, 100),
    (0xDA01EE641A708DEA, 295, 108), (0xA26DA3999AEF774A, 322, 116), (0xF209787BB47D6B85, 348, 124),
    (0xB454E4A179DD1877, 375, 132), (0x865B86925B9BC5C2, 402, 140), (0xC83553C5C8965D3D, 428, 148),
    (0x952AB45CFA97A0B3, 455, 156), (0xDE469FBD99A05FE3, 481, 164), (0xA59BC234DB398C25, 508, 172),
    (0xF6C69A72A3989F5C, 534, 180), (0xB7DCBF5354E9BECE, 561, 188), (0x88FCF317F22241E2, 588, 196),
    (0xCC20CE9BD35C78A5, 614, 204), (0x98165AF37B2153DF, 641, 212), (0xE2A0B5DC971F303A, 667, 220),
    (0xA8D9D1535CE3B396, 694, 228), (0xFB9B7CD9A4A7443C, 720, 236), (0xBB764C4CA7A44410, 747, 244),
    (0x8BAB8EEFB6409C1A, 774, 252), (0xD01FEF10A657842C, 800, 260), (0x9B10A4E5E9913129, 827, 268),
    (0xE7109BFBA19C0C9D, 853, 276), (0xAC2820D9623BF429, 880, 284), (0x80444B5E7AA7CF85, 907, 292),
    (0xBF21E44003ACDD2D, 933, 300), (0x8E679C2F5E44FF8F, 960, 308), (0xD433179D9C8CB841, 986, 316),
    (0x9E19DB92B4E31BA9, 1013, 324),
)
_POW10 = tuple(10 ** i for i in range(10))


def _grisu2(x: float) -> tuple[str, int]:
    """nlohmann's dtoa_impl::grisu2 for a finite x > 0: (digits, decimal_exponent), x ~= digits * 10^exponent.

    Python ints do not wrap, and nothing here needs them to: diyfp::mul (four 32-bit partial products,
    the low half of the lowest dropped, + 2^31 to round ties up) is ((x*y >> 32) + 2^31) >> 32 on the
    exact 128-bit product, always below 2^64; every other uint64 operation of to_chars.hpp stays in
    range (its asserts say so), so no mask is needed.
    """
    # compute_boundaries
    bits = struct.unpack("<Q", struct.pack("<d", x))[0]
    E, F = bits >> 52, bits & 0xFFFFFFFFFFFFF
    if E == 0:
        vf, ve = F, -1074
    else:
        vf, ve = F | 0x10000000000000, E - 1075
    mp_f, mp_e = 2 * vf + 1, ve - 1
    if F == 0 and E > 1:  # the lower boundary is closer
        mm_f, mm_e = 4 * vf - 1, ve - 2
    else:
        mm_f, mm_e = 2 * vf - 1, ve - 1
    s = 64 - mp_f.bit_length()              # diyfp::normalize(m_plus)
    mp_f <<= s
    e = mp_e - s
    mm_f <<= mm_e - e                       # diyfp::normalize_to(m_minus, e)
    vf <<= 64 - vf.bit_length()             # diyfp::normalize(v): exponent e too (one bit fewer than m_plus)
    # get_cached_power_for_binary_exponent(e)
    f = -61 - e                             # kAlpha - e - 1
    k = (f * 78913) // 262144 if f >= 0 else -((-f * 78913) // 262144)  # C++ division truncates toward zero
    k += f > 0
    c_f, c_e, c_k = _CACHED_POWERS[(300 + k + 7) // 8]
    # diyfp::mul: the upper 64 bits of the product, rounded (ties up); exponent e + c_e + 64
    w_f = (((vf * c_f) >> 32) + 0x80000000) >> 32
    M_minus = ((((mm_f * c_f) >> 32) + 0x80000000) >> 32) + 1
    M_plus = ((((mp_f * c_f) >> 32) + 0x80000000) >> 32) - 1
    decimal_exponent = -c_k
    # grisu2_digit_gen
    one_e = -(e + c_e + 64)                 # -M_plus.e, in 32..60
    one_f = 1 << one_e
    delta = M_plus - M_minus
    dist = M_plus - w_f
    p1 = M_plus >> one_e
    p2 = M_plus & (one_f - 1)
    n = len(str(p1))                        # find_largest_pow10 (p1 > 0)
    pow10 = _POW10[n - 1]
    digits = []
    while n > 0:
        d, p1 = divmod(p1, pow10)
        digits.append(d)
        n -= 1
        rest = (p1 << one_e) + p2
        if rest <= delta:
            decimal_exponent += n
            ten_k = pow10 << one_e
            break
        pow10 //= 10
    else:
        m = 0
        while True:
            p2 *= 10
            digits.append(p2 >> one_e)
            p2 &= one_f - 1
            m += 1
            delta *= 10
            dist *= 10
            if p2 <= delta:
                break
        decimal_exponent -= m
        rest, ten_k = p2, one_f
    # grisu2_round
    while rest < dist and delta - rest >= ten_k and (rest + ten_k < dist or dist - rest > rest + ten_k - dist):
        digits[-1] -= 1
        rest += ten_k
    return "".join(map(str, digits)), decimal_exponent


def _dump_float(x: float) -> str:
    """dump()'s text of a double: nlohmann/detail/conversions/to_chars.hpp (Grisu2, then format_buffer
    with exponents -4..15), "null" for what is not finite (serializer::dump_float)."""
    if not math.isfinite(x):
        return "null"
    if x == 0:
        return "-0.0" if math.copysign(1, x) < 0 else "0.0"
    digits, exponent = _grisu2(abs(x))
    k, n = len(digits), len(digits) + exponent
    if k <= n <= 15:
        text = digits + "0" * (n - k) + ".0"
    elif 0 < n <= 15:
        text = digits[:n] + "." + digits[n:]
    elif -4 < n <= 0:
        text = "0." + "0" * (-n) + digits
    else:
        e = n - 1
        text = (digits if k == 1 else digits[0] + "." + digits[1:]) + f"e{'-' if e < 0 else '+'}{abs(e):02d}"
    return ("-" if x < 0 else "") + text


def _dump(v) -> str:
    if isinstance(v, dict):
        return "{" + ",".join(json.dumps(k, ensure_ascii=False) + ":" + _dump(v[k]) for k in sorted(v)) + "}"
    if isinstance(v, list):
        return "[" + ",".join(_dump(x) for x in v) + "]"
    if isinstance(v, _Token):
        return str(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, bool) or v is None:
        return {True: "true", False: "false", None: "null"}[v]
    if isinstance(v, int):
        return str(v)
    return _dump_float(v)


def summary_content_hashes(summary: dict, text: str) -> set[str]:
    """The summary_json_hash summary.json (parsed as `summary`, read as `text`) may carry."""
    spelled = json.loads(text, parse_float=_Token, parse_int=_Token)
    try:
        return {fnv1a64(_dump(spelled).encode("utf-8")), fnv1a64(_dump(summary).encode("utf-8"))}
    except UnicodeEncodeError:  # a lone surrogate written as an escape: not text nlohmann reads
        return set()



def _summary(path: str) -> tuple[dict, str]:
    """summary.json parsed (the fields load() uses of the right kind), and its text."""
    data = read_file(path, MAX_SUMMARY_BYTES, "summary.json")
    s = parse_json(data, path)
    if not isinstance(s, dict):
        raise ResultsError(f"{path}: not a granrepro summary (a JSON object)")
    if s.get("schema", "granrepro-summary") != "granrepro-summary":
        raise ResultsError(f"{path}: not a granrepro summary (schema: {str(s.get('schema'))[:40]!r})")
    if "schema_version" in s and s["schema_version"] not in READS_VERSIONS:
        raise ResultsError(f"{path}: schema_version {str(s['schema_version'])[:20]}, this reader knows {READS_VERSIONS}")
    for key, kind in (("parameters", dict), ("scalars", dict), ("units", dict), ("claims", list),
                      ("data_h5_hash", dict), ("overridden_parameters", dict)):
        if key in s and not isinstance(s[key], kind):
            raise ResultsError(f"{path}: '{key}' must be a JSON {'object' if kind is dict else 'array'}")
    for name, p in s.get("parameters", {}).items():
        if not isinstance(p, dict) or "value" not in p:
            raise ResultsError(f"{path}: parameters.{name} must be an object with a 'value'")
    for i, c in enumerate(s.get("claims", [])):
        if not isinstance(c, dict) or not isinstance(c.get("id"), str):
            raise ResultsError(f"{path}: claims[{i}] must be an object with a text 'id'")
    return s, data.decode("utf-8")


def _show(v) -> str:
    text = repr(v.tolist()) if isinstance(v, np.ndarray) else repr(v)
    return text if len(text) <= 60 else text[:57] + "..."


def _same_value(h5, kind: str, js) -> bool:
    """A /parameters value (of `kind`: flag, integer, real, reals, text) equals summary.json's."""
    def real(a, b):
        if b is None:
            return math.isnan(a)
        return isinstance(b, (int, float)) and not isinstance(b, bool) and float(b) == a
    if kind == "flag":
        return isinstance(js, bool) and js == h5
    if kind == "integer":
        return isinstance(js, int) and not isinstance(js, bool) and js == h5
    if kind == "real":
        return real(h5, js)
    if kind == "reals":
        return isinstance(js, list) and len(js) == len(h5) and all(real(float(a), b) for a, b in zip(h5, js))
    return isinstance(js, str) and js == h5


def _mismatch(h5_path: str, what: str, experiment: str):
    raise ResultsMismatch(f"{h5_path}: {what} (one of the two was edited); rerun `granrepro {experiment}`")


def _check_parameters(h5_path: str, run: Run, kinds: dict, summary: dict) -> None:
    sp = summary.get("parameters", {})
    for name, q in run.parameters.items():
        if name not in sp:
            _mismatch(h5_path, f"/parameters/{name} is not in summary.json beside it", run.experiment)
        js = sp[name]
        if not _same_value(q.value, kinds[name], js.get("value")):
            _mismatch(h5_path, f"/parameters/{name} is {_show(q.value)} but summary.json beside it has "
                               f"{_show(js.get('value'))}", run.experiment)
        if kinds[name] != "text" and js.get("unit", q.unit) != q.unit:
            _mismatch(h5_path, f"the unit of /parameters/{name} is {q.unit!r} but summary.json beside it has "
                               f"{_show(js.get('unit'))}", run.experiment)
        if js.get("source", q.source) != q.source:
            _mismatch(h5_path, f"the source of /parameters/{name} differs from summary.json's", run.experiment)
    for name in sp:
        if name not in run.parameters:
            _mismatch(h5_path, f"has no /parameters/{name} (summary.json beside it has it)", run.experiment)


def _check_against_summary(h5_path: str, run: Run, summary: dict, text: str, found: dict) -> None:
    """data.h5 against summary.json, as `granrepro check` verifies them (src/harness/runner.cpp)."""
    for key, mine in (("experiment", run.experiment), ("scale", run.scale), ("seed", run.seed)):
        if summary.get(key) != mine or isinstance(summary.get(key), bool):
            _mismatch(h5_path, f"'{key}' is {_show(mine)} but summary.json beside it has {_show(summary.get(key))}",
                      run.experiment)
    for key in ("code_version", "physics_hash"):
        if key in run.attributes and key in summary and summary[key] != run.attributes[key]:
            _mismatch(h5_path, f"'{key}' differs from summary.json's", run.experiment)
    for name, js in summary.get("scalars", {}).items():
        q = run.scalars.get(name)
        if q is None:
            _mismatch(h5_path, f"has no /scalars/{name} (summary.json beside it has it)", run.experiment)
        if not (math.isnan(q.value) if js is None else
                isinstance(js, (int, float)) and not isinstance(js, bool) and float(js) == q.value):
            _mismatch(h5_path, f"/scalars/{name} is {_show(q.value)} but summary.json beside it has {_show(js)}",
                      run.experiment)
    if "summary_json_hash" not in run.attributes:
        _mismatch(h5_path, "has no summary_json_hash", run.experiment)
    if run.attributes["summary_json_hash"] not in summary_content_hashes(summary, text):
        raise ResultsMismatch(f"{os.path.join(run.path, 'summary.json')}: content differs from the hash data.h5 "
                              f"beside it recorded for it (edited since the run?); rerun `granrepro {run.experiment}`")
    recorded = summary.get("data_h5_hash")
    if not isinstance(recorded, dict):
        _mismatch(h5_path, "summary.json beside it has no 'data_h5_hash' object", run.experiment)
    if recorded.get("scalars") != found["scalars"]:
        _mismatch(h5_path, "its scalars differ from the hash summary.json recorded for them", run.experiment)
    if "points" in found and recorded.get("points") != found["points"]:  # read only with points=True
        _mismatch(h5_path, "its stored sweep points (/points) differ from the hash summary.json recorded for them",
                  run.experiment)
    tables = recorded.get("tables", {})
    for name, h in found["tables"].items():
        if not isinstance(tables, dict) or tables.get(name) != h:
            _mismatch(h5_path, f"table '{name}' differs from the hash summary.json recorded for it", run.experiment)
    _check_parameters(h5_path, run, found["parameter_kinds"], summary)


# ---------------------------------------------------------------- load


def _parameters(h5: _H5, f, run: Run) -> dict:
    """Fills run.parameters; returns each parameter's kind (flag, integer, real, reals, text)."""
    pg = h5.group(f, "parameters", "/")
    pattrs = h5.attrs(pg, "/parameters")
    kinds = {}
    what = "a parameter is a float64, an int64, a uint8 flag or a 1-D float64 list"
    for name in _in_creation_order(h5, pg, "/parameters"):
        ds, v = h5.dataset(pg, name, "/parameters", "fiu", (0, 1), what)
        if ds.ndim == 1:
            kinds[name] = "reals"
        elif ds.dtype == np.uint8:
            v, kinds[name] = bool(v), "flag"
        elif ds.dtype.kind == "f":
            v, kinds[name] = float(v), "real"
        else:
            v, kinds[name] = int(v), "integer"
        a = h5.attrs(ds, f"/parameters/{name}")
        run.parameters[name] = Quantity(v, _as_text(h5, a, "unit", name), _as_text(h5, a, "description", name),
                                        _as_text(h5, pattrs, name + ".source", "/parameters"))
    for k, v in pattrs.items():  # text parameters
        if not k.endswith(".source"):
            if not isinstance(v, str):
                h5.refuse(f"attribute '{k}' of /parameters is a number; a text parameter is text")
            run.parameters[k] = Quantity(v, "", "", _as_text(h5, pattrs, k + ".source", "/parameters"))
            kinds[k] = "text"
    return kinds


def _as_text(h5: _H5, attrs: dict, key: str, where: str) -> str:
    v = attrs.get(key, "")
    if not isinstance(v, str):
        h5.refuse(f"attribute '{key}' of {where} is a number; granrepro writes text")
    return v


def _read_h5(h5_path: str, out_dir: str, tables, points: bool) -> tuple[Run, dict]:
    h5 = _H5(h5_path)
    require_regular_file(h5_path, "data.h5")
    try:
        f = h5py.File(h5_path, "r")
    except (OSError, ValueError, RuntimeError) as e:
        raise ResultsError(f"{h5_path}: not a readable HDF5 file (truncated or damaged: {_short(e)}); "
                           "rerun the experiment to replace it") from None
    with f:
        root = h5.attrs(f, "/")
        if root.get("schema") != SCHEMA:
            raise ResultsError(f"{h5_path}: not a {SCHEMA} file (schema: {_show(root.get('schema'))})")
        version = root.get("schema_version")
        if version not in READS_VERSIONS or isinstance(version, str):
            raise ResultsError(f"{h5_path}: schema_version {_show(version)}, this reader knows {READS_VERSIONS}")
        for key in ("experiment", "scale"):
            if not isinstance(root.get(key), str):
                h5.refuse(f"root attribute '{key}' is missing or not text")
        seed = root.get("seed")
        if not isinstance(seed, int):
            h5.refuse("root attribute 'seed' is missing or not an integer")
        run = Run(path=out_dir, experiment=root["experiment"], scale=root["scale"], seed=seed, attributes=root)
        found = {"parameter_kinds": _parameters(h5, f, run), "tables": {}}
        scalar_hash = _ContentHash()
        sg = h5.group(f, "scalars", "/")
        for name in _in_creation_order(h5, sg, "/scalars"):
            ds, v = h5.dataset(sg, name, "/scalars", "fiu", (0, 1), "a scalar is one float64")
            if np.size(v) != 1:
                h5.refuse(f"/scalars/{name} holds {np.size(v)} values; a scalar is one float64")
            a = h5.attrs(ds, f"/scalars/{name}")
            q = Quantity(float(np.asarray(v, dtype="<f8").reshape(-1)[0]), _as_text(h5, a, "unit", f"/scalars/{name}"),
                         _as_text(h5, a, "description", f"/scalars/{name}"))
            scalar_hash.column(name, q.unit, [q.value])
            run.scalars[name] = q
        found["scalars"] = scalar_hash.hex()
        tg = h5.group(f, "tables", "/")
        names = _in_creation_order(h5, tg, "/tables")
        wanted = tables(names) if callable(tables) else tables
        for tname in names:
            if wanted is not None and tname not in wanted:
                continue
            g = h5.group(tg, tname, "/tables")
            where = f"/tables/{tname}"
            t = Table(tname, h5.text_attr(g, where, "description", ""))
            th = _ContentHash()
            th.text(tname)
            for c in _in_creation_order(h5, g, where):
                ds, v = h5.dataset(g, c, where, "fiu", (1,), "a table column is 1-D float64")
                t[c] = v
                t.units[c] = h5.text_attr(ds, f"{where}/{c}", "unit", "")
                th.column(c, t.units[c], v)
            run.tables[tname] = t
            found["tables"][tname] = th.hex()
        if h5._read(lambda: "provenance" in f, "/provenance"):
            run.provenance = h5.attrs(h5.group(f, "provenance", "/"), "/provenance")
        if points:
            found["points"] = None  # summary.json must then record no points hash either
        if points and h5._read(lambda: "points" in f, "/points"):
            pg = h5.group(f, "points", "/")
            if h5._read(lambda: "records" not in pg, "/points"):
                h5.refuse("/points has no dataset 'records'")
            _, raw = h5.dataset(pg, "records", "/points", "u", (1,), "the stored points are 1-D uint8 JSON text")
            data = np.asarray(raw, dtype=np.uint8).tobytes()
            run.points = parse_json(data, f"{h5_path} /points/records")
            if not isinstance(run.points, list):
                h5.refuse("/points/records is not a JSON array")
            full = h5.text_attr(pg, "/points", "full_records_hash", "") or fnv1a64(data)
            found["points"] = full
    return run, found


def load(out_dir: str, tables=None, points: bool = True) -> Run:
    """Reads OUT/<experiment>/ (the folder holding data.h5 and summary.json) and verifies the two
    against each other. tables: the names of the tables to read (default: every one), or a function
    from the names in the file to those; parameters, scalars and provenance are always read.
    points=False leaves /points unread (run.points empty): hashing it in Python takes about a
    second per 10 MB.
    Raises ResultsError (one line naming the file and field) on anything damaged or edited."""
    h5_path = os.path.join(out_dir, "data.h5")
    summary_path = os.path.join(out_dir, "summary.json")
    run, found = _read_h5(h5_path, out_dir, tables, points)
    summary, text = _summary(summary_path)
    _check_against_summary(h5_path, run, summary, text, found)
    run.summary = summary
    run.claims = summary.get("claims", [])
    return run
