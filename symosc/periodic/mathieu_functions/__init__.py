"""Mathieu functions: ce, se, modified functions, Floquet exponent and solutions."""
