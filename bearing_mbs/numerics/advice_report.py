"""The step advice as plain text, for the command line."""

from __future__ import annotations

import math


def advice_report(applies: bool, reason: str, operating_point: dict, modes, limits: dict) -> str:
    """The operating point, the modes (fastest first) and the table of limits [s].

    ``limits``: "engine/method" → (limit or None or inf, recommended or None, controlling mode).
    """
    if not applies:
        return f"no advice: {reason}"
    op = operating_point
    lines = [
        f"operating point: applied load {op['static_load']:.4g} N, peak {op['peak_load']:.4g} N "
        f"(dynamic factor {op['load_factor']:.3g}); shaft {op['shaft_speed']:.4g} rad/s; "
        f"centrifugal force {op['centrifugal_force']:.4g} N (peak {op['peak_centrifugal_force']:.4g} N)",
        f"largest roller load: {op['max_roller_load']:.4g} N static, {op['peak_roller_load']:.4g} N at the peak",
        "",
        "modes (linearised at the peak loads):",
    ]
    for mode in sorted(modes, key=lambda m: -m.rate):
        kind = ("decay" if mode.alpha == 0 else
                f"omega = {math.sqrt(-mode.alpha):.3g} rad/s, 2 sigma = {abs(mode.beta):.3g} 1/s")
        lines.append(f"  {mode.name:<32} {mode.where:<11} |s| = {mode.rate:9.3g} 1/s  ({kind})")
    lines += ["", f"{'engine/method':<30} {'limit [s]':>10} {'advised [s]':>12}  set by"]
    for key, (limit, recommended, mode) in limits.items():
        if limit is None:
            lines.append(f"{key:<30} {'-':>10} {'-':>12}  no stability formula for this solver")
        elif not math.isfinite(limit):
            lines.append(f"{key:<30} {'none':>10} {'-':>12}  implicit: choose the step for accuracy "
                         "(bearing-mbs convergence)")
        elif recommended is None:
            lines.append(f"{key:<30} {limit:10.3g} {'-':>12}  {mode}: unstable at any step")
        else:
            lines.append(f"{key:<30} {limit:10.3g} {recommended:12.2g}  {mode}")
    return "\n".join(lines)
