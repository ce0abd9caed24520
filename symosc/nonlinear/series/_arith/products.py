"""Products of truncated Fourier series: FLINT integer polynomials (exact and fixed point) and float helpers.

Used by :mod:`symosc.nonlinear.series._fourier`; the functions take ``flint.fmpz_poly`` as an argument (python-flint is
optional and imported there).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from .trig import Trig


def _object_array(values: list) -> np.ndarray:
    """Python ints in an object array (never converted to a fixed-width integer type)."""
    out = np.empty(len(values), dtype=object)
    out[:] = values
    return out


def _int_list(p: Any, n: int) -> list:
    out = [int(c) for c in p.coeffs()]
    return out + [0] * (n - len(out))


def _int_products_flint(P: Any, ac, as_, bc, bs, na: int, nb: int) -> tuple[list, list, list, list]:
    """The n + m and n - m convolutions of integer numerators by FLINT (6 products, Karatsuba-style).

    Returns (cc - ss, sc + cs, dcc + dss, dsc - dcs) as int lists of length na + nb + 1, the same integers as the
    eight :func:`numpy.convolve` calls of :meth:`_Arith._products`.
    """
    a_c, a_s = P(ac.tolist()), P(as_.tolist())
    b_c, b_s = P(bc.tolist()), P(bs.tolist())
    r_c, r_s = P(bc[::-1].tolist()), P(bs[::-1].tolist())
    a_sum = a_c + a_s
    p1, p2, p3 = a_c * b_c, a_s * b_s, a_sum * (b_c + b_s)
    p4, p5, p6 = a_c * r_c, a_s * r_s, a_sum * (r_c - r_s)
    n = na + nb + 1
    return (
        _int_list(p1 - p2, n),
        _int_list(p3 - p1 - p2, n),
        _int_list(p4 + p5, n),
        _int_list(p6 - p4 + p5, n),
    )


def _parity(t: Trig) -> int | None:
    """1 when only odd harmonics occur, 0 when only even ones, None for both (cached on ``t``)."""
    cache = t.polys if t.polys is not None else {}
    if "p" not in cache:
        if not any(t.cos[0::2].tolist()) and not any(t.sin[0::2].tolist()):
            cache["p"] = 1
        elif not any(t.cos[1::2].tolist()) and not any(t.sin[1::2].tolist()):
            cache["p"] = 0
        else:
            cache["p"] = None
        t.polys = cache
    return cache["p"]


def _forward_polys(P: Any, t: Trig, parity: int | None = None) -> tuple:
    """(cos, sin, cos + sin) numerators of ``t`` as ``fmpz_poly`` (cached on ``t``).

    With ``parity`` (0 or 1) only the harmonics of that parity are kept, as a polynomial in ``z**2``.
    """
    cache = t.polys if t.polys is not None else {}
    key = ("f", parity)
    if key not in cache:
        lo = 0 if parity is None else parity
        step = 1 if parity is None else 2
        c, s = P(t.cos[lo::step].tolist()), P(t.sin[lo::step].tolist())
        cache[key] = (c, s, c + s)
        t.polys = cache
    return cache[key]


def _reversed_polys(P: Any, t: Trig, n: int, parity: int | None = None) -> tuple:
    """Reversed numerators shifted to degree ``n`` (the n - m terms), their difference, and the forward forms.

    With ``parity`` (of the harmonics of ``t``) the reversed polynomials are taken in ``z**2`` from the offset
    ``(n - parity) % 2``.
    """
    cache = t.polys if t.polys is not None else {}
    key = ("r", n, parity)
    if key not in cache:
        rc, rs, rd = _reversed_base(P, t, parity)
        shift = _reversal_shift(t, n, parity)
        if shift:
            rc, rs, rd = rc.left_shift(shift), rs.left_shift(shift), rd.left_shift(shift)
        cache[key] = (rc, rs, rd, *_forward_polys(P, t, parity))
        t.polys = cache
    return cache[key]


def _reversed_base(P: Any, t: Trig, parity: int | None) -> tuple:
    """Reversed (cos, sin, cos - sin) numerators of ``t`` at its own length (cached on ``t``)."""
    cache = t.polys if t.polys is not None else {}
    key = ("r0", parity)
    if key not in cache:
        rc, rs = t.cos[::-1].tolist(), t.sin[::-1].tolist()
        if parity is not None:
            lo = (len(t.cos) - 1 - parity) % 2
            rc, rs = rc[lo::2], rs[lo::2]
        rc, rs = P(rc), P(rs)
        cache[key] = (rc, rs, rc - rs)
        t.polys = cache
    return cache[key]


def _reversal_shift(t: Trig, n: int, parity: int | None) -> int:
    """Power of ``z`` (of ``z**2`` with ``parity``) that moves the reversal of ``t`` to degree ``n``."""
    own = len(t.cos) - 1
    if parity is None:
        return n - own
    return ((n - (n - parity) % 2) - (own - (own - parity) % 2)) // 2


def _pure_plan(P: Any, t: Trig, parity: int | None) -> tuple | None:
    """For a pure cosine or sine series: (kind, forward poly, reversed poly, reference degree), else None.

    The reversed polynomial is taken at ``t``'s own length; the reference degree (``own`` rounded down to the
    parity) tells by how much a product with it must be shifted to stand for the reversal at another length.
    """
    cache = t.polys if t.polys is not None else {}
    key = ("plan", parity)
    if key not in cache:
        kind = _kind(t)
        if kind is None:
            cache[key] = None
        else:
            i = 0 if kind == "c" else 1
            own = len(t.cos) - 1
            ref = own if parity is None else own - (own - parity) % 2
            cache[key] = (kind, _forward_polys(P, t, parity)[i], _reversed_base(P, t, parity)[i], ref)
        t.polys = cache
    return cache[key]


def _kind(t: Trig) -> str | None:
    """ "c" when the sine numerators all vanish, "s" when the cosine ones do, None otherwise (cached on ``t``)."""
    cache = t.polys if t.polys is not None else {}
    if "k" not in cache:
        if not any(t.sin.tolist()):
            cache["k"] = "c"
        elif not any(t.cos.tolist()):
            cache["k"] = "s"
        else:
            cache["k"] = None
        t.polys = cache
    return cache["k"]


def _spread(p: Any, offset: int, n: int) -> np.ndarray:
    """Coefficients of ``z**offset * p(z**2)`` as an object array of length ``n``."""
    out = [0] * n
    m = len(range(offset, n, 2))
    out[offset::2] = _int_list(p, m)
    return _object_array(out)


def _flint_dot(P: Any, pairs: list[tuple[Trig, Trig]], factors: list[int]) -> tuple[np.ndarray, np.ndarray]:
    """Twice the numerators of ``sum f * a * b`` (integer numerators; ``f`` in ``factors``) by FLINT products.

    Odd-only or even-only harmonics on each side (odd nonlinearities) are multiplied as polynomials in ``z**2``.
    """
    na = max(len(a.cos) for a, _ in pairs) - 1
    nb = max(len(b.cos) for _, b in pairs) - 1
    zero = P(0)
    acc = [zero, zero, zero, zero]
    par_a = {_parity(a) for a, _ in pairs}
    par_b = {_parity(b) for _, b in pairs}
    if len(par_a) == 1 and len(par_b) == 1 and None not in par_a and None not in par_b:
        pa, pb = par_a.pop(), par_b.pop()
        q = (nb - pb) % 2
        offsets: tuple | None = (pa + pb, pa + pb, pa + q, pa + q)
    else:
        pa = pb = None
        offsets = None
    ref_b = nb if pb is None else nb - (nb - pb) % 2
    step = 1 if pb is None else 2
    for (a, b), f in zip(pairs, factors, strict=True):
        plan_a, plan_b = _pure_plan(P, a, pa), _pure_plan(P, b, pb)
        if plan_a is not None and plan_b is not None:
            # one part of each factor vanishes: two products (n + m and n - m) instead of six
            ka, x, _, _ = plan_a
            kb, y, ry, ref = plan_b
            if f != 1:
                x = x * f
            plus, minus = x * y, x * ry
            if ref != ref_b:
                minus = minus.left_shift((ref_b - ref) // step)
            if ka == kb:  # cos cos = (cos(n+m) + cos(n-m))/2, sin sin = (cos(n-m) - cos(n+m))/2
                acc[0] = acc[0] + plus if ka == "c" else acc[0] - plus
                acc[2] += minus
            else:  # cos sin = (sin(n+m) - sin(n-m))/2, sin cos = (sin(n+m) + sin(n-m))/2
                acc[1] += plus
                acc[3] = acc[3] - minus if ka == "c" else acc[3] + minus
            continue
        a_c, a_s, a_sum = _forward_polys(P, a, pa)
        r_c, r_s, r_diff, b_c, b_s, b_sum = _reversed_polys(P, b, nb, pb)
        p1, p2, p3 = a_c * b_c, a_s * b_s, a_sum * b_sum
        p4, p5, p6 = a_c * r_c, a_s * r_s, a_sum * r_diff
        if f == 1:
            acc[0] += p1 - p2
            acc[1] += p3 - p1 - p2
            acc[2] += p4 + p5
            acc[3] += p6 - p4 + p5
        else:
            acc[0] += (p1 - p2) * f
            acc[1] += (p3 - p1 - p2) * f
            acc[2] += (p4 + p5) * f
            acc[3] += (p6 - p4 + p5) * f
    n = na + nb
    if offsets is None:
        out_c, out_s, dc, ds = (_object_array(_int_list(p, n + 1)) for p in acc)
    else:
        out_c, out_s, dc, ds = (_spread(p, off, n + 1) for p, off in zip(acc, offsets, strict=True))
    _fold_differences(out_c, out_s, dc, ds, na, nb)
    top = max(len(a.cos) + len(b.cos) - 1 for a, b in pairs)  # as long as the longest single product
    return out_c[:top].copy(), out_s[:top].copy()


def _flint_lincomb(P: Any, scalars: list, series: list[Trig], factors: list[int], n: int) -> tuple:
    """Numerators of ``sum s * t`` (Fraction ``s``; ``factors`` bring each term to the common denominator).

    Summed as FLINT polynomials (in ``z**2`` when every term has only odd or only even harmonics).
    """
    used = [(c.numerator * f, t) for c, t, f in zip(scalars, series, factors, strict=True) if c.numerator != 0]
    parities = {_parity(t) for _, t in used}
    parity = parities.pop() if len(parities) == 1 else None
    acc_c = acc_s = P(0)
    for f, t in used:
        c, s, _ = _forward_polys(P, t, parity)
        acc_c += c * f
        acc_s += s * f
    if parity is None:
        return _object_array(_int_list(acc_c, n)), _object_array(_int_list(acc_s, n))
    return _spread(acc_c, parity, n), _spread(acc_s, parity, n)


def _fold_differences(out_c, out_s, dc, ds, na: int, nb: int) -> None:
    """Add the n - m terms (``dc``/``ds`` index j + nb holds n - m = j) into the n + m sums, in place."""
    out_c[: na + 1] = out_c[: na + 1] + dc[nb : nb + na + 1]
    out_s[: na + 1] = out_s[: na + 1] + ds[nb : nb + na + 1]
    if nb > 0:
        out_c[1 : nb + 1] = out_c[1 : nb + 1] + dc[:nb][::-1]
        out_s[1 : nb + 1] = out_s[1 : nb + 1] - ds[:nb][::-1]
    out_s[0] = 0


def _float_structure(t: Trig) -> Any:
    """("c" | "s" | None, parity | None) of a float series, or "0" for the zero series (cached on ``t``)."""
    cache = t.polys if t.polys is not None else {}
    if "fs" not in cache:
        c, s = t.cos, t.sin
        has_c, has_s = bool(c.any()), bool(s.any())
        if not has_c and not has_s:
            cache["fs"] = "0"
        else:
            kind = None if has_c and has_s else ("c" if has_c else "s")
            if not c[0::2].any() and not s[0::2].any():
                parity = 1
            elif not c[1::2].any() and not s[1::2].any():
                parity = 0
            else:
                parity = None
            cache["fs"] = (kind, parity)
        t.polys = cache
    return cache["fs"]


def _float_direct_dot(pairs: list[tuple[Trig, Trig]], products: Any) -> tuple[np.ndarray, np.ndarray]:
    """``sum a * b`` of float series by direct convolution (each coefficient a plain sum of products).

    Pairs of pure cosine/sine series with odd-only or even-only harmonics (the usual case for odd nonlinearities)
    take two :func:`numpy.convolve` calls on the half-length arrays: the ``n + m`` terms, and the ``n - m`` terms
    from the reversed second factor.  Other pairs go through ``products(a, b)`` (twice the product, all terms).
    """
    top = max(len(a.cos) + len(b.cos) - 1 for a, b in pairs)
    out_c = np.zeros(top)
    out_s = np.zeros(top)
    structured = []
    for a, b in pairs:
        sa, sb = _float_structure(a), _float_structure(b)
        if sa == "0" or sb == "0":
            continue
        if sa[0] is None or sb[0] is None or sa[1] is None or sb[1] is None:
            c, s = products(a, b)
            out_c[: len(c)] += c
            out_s[: len(s)] += s
            continue
        structured.append((a, b, sa, sb))
    groups: dict[tuple[int, int], list] = {}
    for a, b, sa, sb in structured:
        groups.setdefault((sa[1], sb[1]), []).append((a, b, sa[0], sb[0]))
    for (pa, pb), group in groups.items():
        lb_max = max((len(b.cos) - 1 - pb) // 2 + 1 for _, b, _, _ in group)
        la_max = max((len(a.cos) - 1 - pa) // 2 + 1 for a, _, _, _ in group)
        plus = {"c": np.zeros(la_max + lb_max - 1), "s": np.zeros(la_max + lb_max - 1)}
        minus = {"c": np.zeros(la_max + lb_max - 1), "s": np.zeros(la_max + lb_max - 1)}
        for a, b, ka, kb in group:
            x = (a.cos if ka == "c" else a.sin)[pa::2]
            y = (b.cos if kb == "c" else b.sin)[pb::2]
            p = np.convolve(x, y)
            q = np.convolve(x, y[::-1])
            lo = lb_max - len(y)  # q[s] is the harmonic difference pa - pb - 2 (len(y) - 1) + 2 s
            if ka == kb:  # cos cos = (cos(n+m) + cos(n-m))/2, sin sin = (cos(n-m) - cos(n+m))/2
                if ka == "c":
                    plus["c"][: len(p)] += p
                else:
                    plus["c"][: len(p)] -= p
                minus["c"][lo : lo + len(q)] += q
            else:  # cos sin = (sin(n+m) - sin(n-m))/2, sin cos = (sin(n+m) + sin(n-m))/2
                plus["s"][: len(p)] += p
                if ka == "c":
                    minus["s"][lo : lo + len(q)] -= q
                else:
                    minus["s"][lo : lo + len(q)] += q
        h = pa + pb + 2 * np.arange(la_max + lb_max - 1)
        keep = h < top
        out_c[h[keep]] += plus["c"][keep]
        out_s[h[keep]] += plus["s"][keep]
        j = pa - pb - 2 * (lb_max - 1) + 2 * np.arange(la_max + lb_max - 1)
        pos, neg = j >= 0, j < 0
        out_c[j[pos]] += minus["c"][pos]
        out_c[-j[neg]] += minus["c"][neg]
        out_s[j[pos]] += minus["s"][pos]
        out_s[-j[neg]] -= minus["s"][neg]
    out_s[0] = 0.0
    return 0.5 * out_c, 0.5 * out_s
