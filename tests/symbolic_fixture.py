"""The solver of the symbolic fixture template (tests/fixtures/symbolic): a formula answer and a number from it."""
from exgen.answertypes.symbolic import Expression

SYMBOLS = ("K", "M", "m")


def pulley_frequency(p, d):
    """Example 6.2: K' = K and m' = 3M/2 + 4m about the axle, so f = sqrt(2K/(3M + 8m))/(2π)."""
    f_expr = d.step("f_expr", Expression.parse("sqrt(2*K/(3*M + 8*m))/(2*pi)", SYMBOLS), symbol="f_n",
                    note="equivalent stiffness K and mass 3M/2 + 4m at the pulley's axle")
    d.mistake("f_expr", "omega_for_f", Expression.parse("sqrt(2*K/(3*M + 8*m))", SYMBOLS))
    d.mistake("f_expr", "point_mass_pulley", Expression.parse("sqrt(K/(M + 4*m))/(2*pi)", SYMBOLS))
    d.step("f", f_expr(K=p.K, M=p.M, m=p.m), "Hz", symbol="f_n",
           formula=r"\frac{1}{2\pi}\sqrt{\frac{2\,@K}{3\,@M + 8\,@m}}")
