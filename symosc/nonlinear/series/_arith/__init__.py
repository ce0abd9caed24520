"""Arithmetic of truncated Fourier polynomials for the series engines (private).

``trig``: the ``Trig`` polynomial and its float, exact (Fraction / FLINT) and fixed-precision arithmetics;
``products``: the products of their coefficient vectors; ``laurent``: the exact engine on half-Laurent numerators
with relaxed Cauchy products.
"""
