"""Engine figures (stub while the drawings are written)."""
from .balancing import _stub

inline_cranks = inline_firing = primary_balance_cranks = radial_cylinders = v_cylinders = _stub
