"""Built-in scenes (available without the source checkout): the Table 1 pendulum behind ``symosc double-pendulum``.

``TABLE1_SCENE`` is the text of ``examples/double_pendulum_frequencies.toml`` (a test keeps them identical).
"""

TABLE1_SCENE = r'''# Natural frequencies and normal modes of the double physical pendulum
# of Gribkov & Khokhlov (2015), Table 1, hanging on a fixed pivot.
# Run:  symosc run examples/double_pendulum_frequencies.toml
title = "Double physical pendulum, Table 1 of Gribkov & Khokhlov (2015)"
source = "Gribkov & Khokhlov (2015), §4, Table 1"

[system]
model = "n_link_pendulum"
n = 2
links = "rigid"          # physical links: mass, centre of mass lc, moment of inertia I about the centre of mass
inverted = false
pivot = "fixed"

[parameters]             # Table 1 (the length l2 of the last link does not enter a chain's equations)
m1 = "1.032 g"
m2 = "0.424 g"
l1 = "45.0 mm"
lc1 = "24.917 mm"
lc2 = "12.838 mm"
I1 = "146.804 g*mm^2"
I2 = "32.871 g*mm^2"
g = "9.81 m/s^2"

[[questions]]
kind = "natural_frequencies"
reference_hz = [2.289, 5.094]
reference_ratio = 0.2019
reference = "Gribkov & Khokhlov (2015), §4"
note = """the paper's 2.289 Hz and 5.094 Hz do not follow from its own Table 1, which gives 2.3276 Hz and \
5.0460 Hz (1.7 % off); lc2 = 15.16 mm instead of 12.838 mm would reproduce them, so a table entry or the \
paper's model differs"""
'''

#: Table 1 of Gribkov & Khokhlov (2015) as scene values (the length l2 of the last link does not enter).
TABLE1_PARAMETERS = {
    "m1": "1.032 g", "m2": "0.424 g", "l1": "45.0 mm", "lc1": "24.917 mm", "lc2": "12.838 mm",
    "I1": "146.804 g*mm^2", "I2": "32.871 g*mm^2", "g": "9.81 m/s^2",
}  # fmt: skip
