"""The questions a scene can ask, one module per family (private to :mod:`symosc.scene`): mechanical systems
(:mod:`.mechanical`: frequencies, matrices, equations, stability, Floquet, sweeps), the other models (:mod:`.other`:
Mathieu values, series, resonance, operational solutions, identification), the time response (:mod:`.time_response`)
and the continuation of periodic solutions (:mod:`.continuation`)."""
