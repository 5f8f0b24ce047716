"""Formatting shared by report.py and its section modules: numbers, Markdown tables, charts and
lists in sentences (the section modules receive it as `rep`)."""
import math

import study_data as sd


def fmt(x, digits=2):
    if not sd.finite(x):
        return "—"
    if x == 0:
        return "0"
    if abs(x) >= 1e4 or abs(x) < 1e-3:
        return f"{x:.{digits - 1}e}"
    return f"{x:.{digits}g}" if abs(x) < 100 else f"{x:.0f}"


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def image(rel, name, alt):
    return f"![{alt}]({rel}/{name}.png)\n\n(also as [SVG]({rel}/{name}.svg))"


def median(xs):
    xs = sorted(x for x in xs if sd.finite(x))
    return xs[len(xs) // 2] if xs else math.nan


def problem_name(title):
    """A problem's name inside a sentence: "the COR 0.5 bounce", "the billiard break"."""
    head = title.split(" (")[0].split(":")[0]
    if ", COR " in head:
        return f"the COR {head.split(', COR ')[1]} bounce"
    if head.startswith("Newton"):
        return head
    return "the " + head[0].lower() + head[1:]


def join(items):
    """"a", "a and b", "a, b and c"."""
    items = list(items)
    if len(items) <= 1:
        return "".join(items)
    return ", ".join(items[:-1]) + " and " + items[-1]
