#!/usr/bin/env python3
"""Writes examples/you2004-fig8d.json: seed 000 Fig. 8d, an aeroplane assembled from patches.

Run from the repository root (or anywhere): python3 scripts/examples/make-aeroplane.py
Standard library only. The scene is scene version 4: chained pde ends, fills, surfaces.

The aeroplane's axis is x, nose at +x, z up, the left wing at -y.

  nose    fill closing front1's u0 (a small section at the nose tip)
  front1  pde: nose section -> circle of radius R at station xa (pure axial tangent)
  front2  pde: continues front1.u1 (tangency) -> circle of radius R at x1 (pure axial tangent)
  rootL/R pde: wing-root blends from a lens-shaped rim in the side plane y = -R / +R
          (cross derivative inside that plane, into the lens) to the wing's root border,
          by reference (tangency)
  wingL/R surfaces: tapered, swept wings with an airfoil-like closed section
  tipL/R  fills closing the wings' tip borders (height 0.3: a round tip)
  mid_top, mid_bottom   4-sided fills of the fuselage between x1 and x2, between front2.u1,
          the two rims and rear1.u0
  rear1   pde: circle R at x2 (pure axial tangent) -> tapered section at x3
  rear2   pde: continues rear1.u1 (tangency) -> small raised section at the tail tip
  tail    fill closing rear2.u1
"""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.normpath(os.path.join(HERE, "..", "..", "examples", "you2004-fig8d.json"))

# Fuselage stations (fixed numbers; R and the sections are parameters).
X_NOSE, XA, X1, X2, X3, X_TAIL = 5.2, 3.8, 2.2, -0.6, -4.2, -6.6
XM = (X1 + X2) / 2  # the lens centre
RIM_DWELL = 0.05  # the rim's dwell at its rear tip (see below)


def param(value, lo, hi, label):
    return {"value": value, "min": lo, "max": hi, "label": label}


parameters = {
    "R": param(1.0, 0.85, 1.15, "fuselage radius R"),
    "nose_r": param(0.35, 0.2, 0.5, "nose section radius (× R)"),
    "nose_flare": param(1.2, 0.6, 2.0, "nose: radial growth of the tangent at the tip (× R)"),
    "h": param(0.55, 0.4, 0.7, "half-height of the wing-root rim (× R)"),
    "lam": param(0.6, 0.3, 1.0, "rim: inward tangent (× distance to the rim's centre)"),
    "rim_p": param(1.0, 0.5, 1.6, "power of the root blends at the wings"),
    "wing_x": param(0.0, -0.25, 0.25, "wing position along the fuselage (moves the wing; the root blends follow)"),
    "gap": param(0.7, 0.5, 1.0, "distance of the wing root outside the fuselage side"),
    "span": param(5.0, 3.5, 6.5, "wing span (each side, from the root)"),
    "sweep": param(1.4, 0.0, 2.5, "sweep: how far back the tip's centre lies"),
    "dihedral": param(0.35, 0.0, 0.8, "dihedral: how far up the tip lies"),
    "chord": param(0.9, 0.7, 1.0, "half chord at the root"),
    "taper": param(0.55, 0.2, 0.7, "taper: the tip's chord is (1 - taper) × the root's"),
    "thick": param(0.16, 0.1, 0.22, "half thickness of the wing at the root"),
    "tail_r": param(0.7, 0.55, 0.85, "fuselage section radius at x3 (× R)"),
    "tail_lift": param(0.25, 0.0, 0.4, "rise of the fuselage's centre line at x3 (× R)"),
    "tip_r": param(0.18, 0.1, 0.3, "tail tip section radius (× R)"),
    "tip_lift": param(0.55, 0.2, 0.8, "rise of the tail tip (× R)"),
}

PI = "pi"


def circle_section(xc, r, zc="0"):
    """x, y, z of a circle of radius r (expression) in the plane x = xc, centre height zc."""
    return (f"{xc}", f"({r})*cos(v)", f"({zc}) + ({r})*sin(v)")


def pde(name, boundary=None, ends=None, method=None, v_range=(0, "2*pi")):
    p = {"name": name, "kind": "pde", "v_range": list(v_range), "operator": {"order": 4, "b": 1, "c": 2, "d": 1}}
    if ends:
        p["ends"] = ends
    if boundary:
        p["boundary"] = boundary
    if method:
        p["method"] = method
    return p


def typed(**ends):
    """boundary {x: {u0: [X, Xu], u1: ...}, ...} from ends u0=(X3, Xu3), u1=(...)."""
    out = {"x": {}, "y": {}, "z": {}}
    for end, (pos, der) in ends.items():
        for c, axis in enumerate("xyz"):
            out[axis][end] = [pos[c], der[c]]
    return out


patches = []

# --- front fuselage ------------------------------------------------------------------------
L1 = X_NOSE - XA
L2 = XA - X1
nose_pos = circle_section(X_NOSE, "nose_r*R")
nose_der = (f"{-L1}", "nose_flare*R*cos(v)", "nose_flare*R*sin(v)")
patches.append(pde("front1", boundary=typed(
    u0=(nose_pos, nose_der),
    u1=(circle_section(XA, "R"), (f"{-L1}", "0", "0")))))
patches.append(pde("front2",
                   ends={"u0": {"patch": "front1", "at": "u1", "continuity": "tangency", "power": 1}},
                   boundary=typed(u1=(circle_section(X1, "R"), (f"{-L2}", "0", "0")))))
patches.append({"name": "nose", "kind": "fill", "borders": [{"patch": "front1", "at": "u0"}]})

# --- wing-root rims, blends and wings ------------------------------------------------------
# The rim, in the plane y = -R (left) / +R (right), is a lens pointed at both ends: x runs
# linearly from x1 (v = 0) to x2 over the top and back underneath, z = h R sin(phi). The front tip
# is the seam (v = 0 and 2 pi); at the rear tip the rim dwells for v in [pi - E, pi + E], so that
# each branch's own tangent is found where the fills' sides end (an expression's derivative at a
# kink is the mean of the two one-sided ones: half the branch's tangent next to a dwell, the
# right direction; at a bare kink the two branches' tangents would cancel in x). The rim's cross
# derivative (into the root blend) is -lam (h R cos phi, 0, A sin phi): smooth in v, inside the
# plane, transversal to the rim everywhere (along the lens's axis at the tips), so the fills'
# corners at the tips find each branch's tangent plane y = +-R.
E = RIM_DWELL
C1, C2 = 3.141592653589793 - E, 3.141592653589793 + E


def ramp(c, side):
    """(v - c)+, whose derivative at v = c (where the expression's derivative is taken, at the
    fills' corners) is the left one (side "L": 0) or the right one (side "R": 1): the sign's step
    sits 1e-9 past c on that side (the rim moves by 1e-9 of a scene unit there, inside the dwell)."""
    shift = -1e-9 if side == "L" else 1e-9
    return f"(v - {c!r})*0.5*(1 + sign(v - {c - shift!r}))"


PHI = f"{3.141592653589793 / C1!r}*(v - {ramp(C1, 'L')} + {ramp(C2, 'R')})"
rim_x = f"{X1} + {(X2 - X1) / C1!r}*(v - {ramp(C1, 'L')} - {ramp(C2, 'R')})"
rim_z = f"h*R*sin({PHI})"
A = (X1 - X2) / 3.141592653589793  # |dx/dphi| along a branch
RANGE_TOP = [0, C1]
RANGE_BOTTOM = [C2, "2*pi"]


def root_blend(name, side, wing):
    y = "-R" if side < 0 else "R"
    pos = (rim_x, y, rim_z)
    der = (f"-lam*h*R*cos({PHI})", "0", f"-lam*{A!r}*sin({PHI})")
    b = typed(u0=(pos, der))
    for axis in "xyz":
        b[axis] = {"u0": b[axis]["u0"]}
    return pde(name, boundary=b,
               ends={"u1": {"surface": wing, "at": "t0", "continuity": "tangency", "power": "rim_p"}},
               method="modal:64")


def wing(name, side):
    s = "-" if side < 0 else ""
    half_chord = "chord*(1 - taper*t)"
    half_thick = "thick*(1 - taper*t)"
    return {
        "name": name, "kind": "surface", "t_range": [0, 1], "v_range": [0, "2*pi"],
        "x": f"{XM} - sweep*t + {half_chord}*cos(v)",
        "y": f"{s}(R + gap + span*t)",
        "z": f"dihedral*t + {half_thick}*sin(v)*(0.8 + 0.35*cos(v))",
        "placement": {"translate": ["wing_x", 0, 0]},
    }


patches.append(root_blend("rootL", -1, "wingL"))
patches.append(root_blend("rootR", +1, "wingR"))
patches.append(wing("wingL", -1))
patches.append(wing("wingR", +1))
# The tip section is thin (thickness/chord about 0.18): at the default height the cap's centre is
# sharp (curvature 307, normal spread 0.25 deg); lifted by 0.3 of the border's rise it is round.
patches.append({"name": "tipL", "kind": "fill", "borders": [{"patch": "wingL", "at": "t1"}], "height": 0.3})
patches.append({"name": "tipR", "kind": "fill", "borders": [{"patch": "wingR", "at": "t1"}], "height": 0.3})

# --- the fuselage between x1 and x2: two 4-sided fills ------------------------------------
# height 1.7: the centre at about the fuselage's top (z = 0.72 R at the default 1: a dip).
patches.append({"name": "mid_top", "kind": "fill", "height": 1.7, "borders": [
    {"patch": "front2", "at": "u1", "range": [0, PI]},
    {"patch": "rootL", "at": "u0", "range": RANGE_TOP},
    {"patch": "rear1", "at": "u0", "range": [0, PI], "reverse": True},
    {"patch": "rootR", "at": "u0", "range": RANGE_TOP, "reverse": True},
]})
patches.append({"name": "mid_bottom", "kind": "fill", "height": 1.7, "borders": [
    {"patch": "front2", "at": "u1", "range": [PI, "2*pi"]},
    {"patch": "rootR", "at": "u0", "range": RANGE_BOTTOM, "reverse": True},
    {"patch": "rear1", "at": "u0", "range": [PI, "2*pi"], "reverse": True},
    {"patch": "rootL", "at": "u0", "range": RANGE_BOTTOM},
]})

# --- rear fuselage ---------------------------------------------------------------------------
L3 = X2 - X3
L4 = X3 - X_TAIL
patches.append(pde("rear1", boundary=typed(
    u0=(circle_section(X2, "R"), (f"{-L3}", "0", "0")),
    u1=(circle_section(X3, "tail_r*R", "tail_lift*R"), (f"{-L3}", "-0.12*R*cos(v)", "0.12*R*(1 - sin(v))")))))
patches.append(pde("rear2",
                   ends={"u0": {"patch": "rear1", "at": "u1", "continuity": "tangency", "power": 1}},
                   boundary=typed(u1=(circle_section(X_TAIL, "tip_r*R", "tip_lift*R"),
                                      (f"{-L4 * 0.5}", "-0.3*R*cos(v)", "-0.3*R*sin(v)")))))
patches.append({"name": "tail", "kind": "fill", "borders": [{"patch": "rear2", "at": "u1"}]})

scene = {
    "format": "pdesurf-scene",
    "version": 4,
    "id": "you2004-fig8d",
    "title": "An aeroplane assembled from patches",
    "description": "",
    "source": {"paper": "seed 000, Fig. 8: models of many patches", "figure": "Fig. 8d"},
    "parameters": parameters,
    "patches": patches,
}

scene["description"] = (
    "Seed 000 Fig. 8d: an aeroplane produced by dividing it into patches and assembling them. "
    "The axis is x (nose at +x), z is up. "
    "Fuselage: 'front1' (fourth-order PDE) runs from a small nose section to a circle of radius R; "
    "'front2' continues its end u1 (a chained end: the same position and cross derivative, so the join is G1) "
    "to a circle of radius R at x1 whose tangent is purely axial; 'nose' is a fill closing front1's u0 with a "
    "regular centre point (G1 to front1). 'rear1' starts at a circle of radius R at x2, again with a purely axial "
    "tangent, and tapers and rises towards the tail; 'rear2' continues it (chained, G1) to a small tail section "
    "closed by the fill 'tail' (G1). "
    "Wing roots: 'rootL' and 'rootR' are fourth-order PDE blends from a lens-shaped rim in the fuselage's side "
    "plane y = -R / y = +R (x running from x1 to x2 and back, z = h R sin phi, pointed at both tips), leaving it "
    "inside that plane into the lens (lam), to the root border t = 0 of the wing surfaces 'wingL' and 'wingR' by reference "
    "(tangency: G1 to the wing, re-derived when a wing moves: wing_x, sweep, dihedral, gap, chord, thick). "
    "The wings are tapered, swept surfaces with an airfoil-like closed section; 'tipL' and 'tipR' are fills "
    "closing their tip borders (G1; their centres are lifted by 0.3 of the border's rise, a round tip). "
    "The fuselage between x1 and x2 is two four-sided fills, 'mid_top' and 'mid_bottom': each runs over half of "
    "front2's end circle, half of each rim and half of rear1's start circle, G1 to all four (front2 and rear1 "
    "end there with a purely axial tangent, so at the rims' tips the four tangent planes agree). "
    "Every join is certified G1 by pdesurf check. pdesurf's construction: the paper gives no data for this figure."
)

with open(OUT, "w") as f:
    json.dump(scene, f, indent=2, ensure_ascii=False)
    f.write("\n")
print(OUT)
