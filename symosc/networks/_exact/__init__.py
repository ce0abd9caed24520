"""Exact arithmetic of the network procedures (private core): polynomials and rational functions over nested number
fields (:mod:`.fields`), tower fields ``L = K[x]/(f(x))`` (:mod:`.tower`).  Used by the synthesis procedures and by
the exact impedance arithmetic of the one-ports."""
