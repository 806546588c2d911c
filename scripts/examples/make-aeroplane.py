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
  rear1   pde: circle R at x2 (pure axial tangent) -> tapered, raised circle at x3 (pure axial)
  stabRootL/R  pde: the horizontal stabilisers' root blends, built like rootL/R from a lens in
          the side plane y = -+ tail_r R of the tail section (x3 to x4) to the stabiliser's root
  stabL/R surfaces: the horizontal stabilisers (tailplanes), smaller swept tapered surfaces
  stabTipL/R  fills closing the stabilisers' tip borders (height 0.3)
  tail_top, tail_bottom  4-sided fills of the fuselage between x3 and x4, between rear1.u1,
          the two stabiliser rims and rear2.u0
  rear2   pde: the same circle at x4 (pure axial tangent) -> small raised section at the tail tip
  tail    fill closing rear2.u1
"""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.normpath(os.path.join(HERE, "..", "..", "examples", "you2004-fig8d.json"))

# Fuselage stations (fixed numbers; R and the sections are parameters).
# Between x1 and x2 the fuselage is a cylinder of radius R (the wing roots), between x3 and x4 one of
# radius tail_r R raised by tail_lift R (the stabilisers' roots).
X_NOSE, XA, X1, X2, X3, X4, X_TAIL = 5.2, 3.8, 2.2, -0.6, -4.0, -5.2, -6.6
XM = (X1 + X2) / 2  # the lens centre
XT = (X3 + X4) / 2  # the tail lens's centre
RIM_DWELL = 0.005  # the rim's dwell at its front tip (see below)


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
    "tail_r": param(0.6, 0.5, 0.75, "fuselage section radius between x3 and x4, at the stabilisers (× R)"),
    "tail_lift": param(0.3, 0.0, 0.4, "rise of the fuselage's centre line between x3 and x4 (× R)"),
    "stab_h": param(0.5, 0.4, 0.65, "half-height of the stabilisers' root rim (× the tail section's radius)"),
    "stab_lam": param(0.6, 0.3, 1.0, "stabiliser rim: inward tangent (× distance to the rim's centre)"),
    "stab_p": param(1.0, 0.5, 1.6, "power of the root blends at the stabilisers"),
    "stab_x": param(0.0, -0.1, 0.1, "stabiliser position along the fuselage (moves the stabilisers; their root blends follow)"),
    "stab_gap": param(0.35, 0.25, 0.5, "distance of the stabiliser root outside the fuselage side"),
    "stab_span": param(1.8, 1.2, 2.4, "stabiliser span (each side, from the root)"),
    "stab_sweep": param(0.6, 0.0, 1.0, "stabiliser sweep: how far back the tip's centre lies"),
    "stab_dihedral": param(0.1, 0.0, 0.3, "stabiliser dihedral: how far up the tip lies"),
    "stab_chord": param(0.4, 0.3, 0.45, "stabiliser half chord at the root"),
    "stab_taper": param(0.5, 0.2, 0.6, "stabiliser taper: the tip's chord is (1 - stab_taper) × the root's"),
    "stab_thick": param(0.07, 0.05, 0.1, "half thickness of the stabiliser at the root"),
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
# linearly from x2 (v = 0) to x1 underneath and back over the top, z = -h R sin(phi). The rear tip
# is the seam (v = 0 and 2 pi), where the wing's trailing edge lies (the root blend runs from
# one to the other along its seam, a sharp edge both ends of which are in its data); at the
# front tip the rim dwells for v in [pi - E, pi + E], so that each branch's own tangent is found
# where the fills' sides end (an expression's derivative at a kink is the mean of the two
# one-sided ones: half the branch's tangent next to a dwell, the right direction; at a bare kink
# the two branches' tangents would cancel in x). The dwell is short (E = 0.005: the blend's
# boundary is still over 1e-2 of its v there) and its corner is carried into the blend only near
# its edge (the modal method's decaying lift for a loop with a corner). The rim's cross
# derivative (into the root blend) is lam (h R cos phi, 0, A sin phi): smooth in v, inside the
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
RANGE_BOTTOM = [0, C1]  # from the rear tip to the front underneath (the surfaces' normals face out)
RANGE_TOP = [C2, "2*pi"]  # from the front tip back over the top


def root_blend(name, side, surface, x_front, x_back, radius, zc, h, lam, power):
    """A root blend from the lens in the plane y = -+radius between x_back (its seam) and x_front
    (centre height zc, half-height h × radius) to the surface's root border t = 0, by reference."""
    rim_x = f"{x_back} + {(x_front - x_back) / C1!r}*(v - {ramp(C1, 'L')} - {ramp(C2, 'R')})"
    half = f"{h}*{radius}"
    rim_z = f"{zc} - {half}*sin({PHI})"
    a = (x_front - x_back) / 3.141592653589793  # |dx/dphi| along a branch
    y = f"-{radius}" if side < 0 else f"{radius}"
    pos = (rim_x, y, rim_z)
    der = (f"{lam}*{half}*cos({PHI})", "0", f"{lam}*{a!r}*sin({PHI})")
    b = typed(u0=(pos, der))
    for axis in "xyz":
        b[axis] = {"u0": b[axis]["u0"]}
    return pde(name, boundary=b,
               ends={"u1": {"surface": surface, "at": "t0", "continuity": "tangency", "power": power}},
               method="modal:64")


# The wings' and stabilisers' section: a symmetric NACA 00xx profile with a closed, sharp
# trailing edge at v = 0 (the surfaces' seam) and a round leading edge at v = pi. With
# r = cos(v/4) - sin(v/4) (1 at v = 0, 0 at pi, -1 at 2 pi), r^2 = 1 - sin(v/2) is the distance
# from the leading edge in chords and r carries the side: lower surface for v in (0, pi), so that t x v faces out. The
# thickness is NACA's, 5 tau (0.2969 sqrt x - 0.1260 x - ...), taken as an odd polynomial in
# r = +-sqrt x, smooth through the leading edge: r (1 - r^2)(2.969 + b1 r^2 + b2 r^4 + b3 r^6), its
# nose term NACA's, b fitted by least squares (within 1.8 % of the half thickness, largest
# 0.99 of it at 30 % chord). The trailing edge is a kink in v at the seam (sin(v/2) is not
# 2 pi-periodic in slope): the only sharp feature, declared by the section's own data.
R_SECTION = "(cos(v/4) - sin(v/4))"
NACA = (f"{R_SECTION}*(1 - {R_SECTION}^2)*(2.969 - 2.085918295172564*{R_SECTION}^2"
        f" + 3.282488016045064*{R_SECTION}^4 - 1.9895231029312184*{R_SECTION}^6)")


def wing(name, side):
    s = "-" if side < 0 else ""
    half_chord = "chord*(1 - taper*t)"
    half_thick = "thick*(1 - taper*t)"
    return {
        "name": name, "kind": "surface", "t_range": [0, 1], "v_range": [0, "2*pi"],
        "x": f"{XM} - sweep*t + {half_chord}*(2*sin(v/2) - 1)",
        "y": f"{s}(R + gap + span*t)",
        "z": f"dihedral*t - {half_thick}*{NACA}",
        "placement": {"translate": ["wing_x", 0, 0]},
    }


def stabiliser(name, side):
    s = "-" if side < 0 else ""
    half_chord = "stab_chord*(1 - stab_taper*t)"
    half_thick = "stab_thick*(1 - stab_taper*t)"
    return {
        "name": name, "kind": "surface", "t_range": [0, 1], "v_range": [0, "2*pi"],
        "x": f"{XT} - stab_sweep*t + {half_chord}*(2*sin(v/2) - 1)",
        "y": f"{s}(tail_r*R + stab_gap + stab_span*t)",
        "z": f"tail_lift*R + stab_dihedral*t - {half_thick}*{NACA}",
        "placement": {"translate": ["stab_x", 0, 0]},
    }


patches.append(root_blend("rootL", -1, "wingL", X1, X2, "R", "0", "h", "lam", "rim_p"))
patches.append(root_blend("rootR", +1, "wingR", X1, X2, "R", "0", "h", "lam", "rim_p"))
patches.append(wing("wingL", -1))
patches.append(wing("wingR", +1))
# The tip section is thin (thickness/chord about 0.18): at the default height the cap's centre is
# sharp (curvature 307, normal spread 0.25 deg); lifted by 0.3 of the border's rise it is round.
patches.append({"name": "tipL", "kind": "fill", "borders": [{"patch": "wingL", "at": "t1"}], "height": 0.3})
patches.append({"name": "tipR", "kind": "fill", "borders": [{"patch": "wingR", "at": "t1"}], "height": 0.3})

# --- the fuselage between x1 and x2: two 4-sided fills ------------------------------------
# Their heights put the centres on the fuselage (z = R at the top): measured with pdesurf check.
MID_HEIGHT, TAIL_HEIGHT = 1.385, 1.92
patches.append({"name": "mid_top", "kind": "fill", "height": MID_HEIGHT, "borders": [
    {"patch": "front2", "at": "u1", "range": [0, PI]},
    {"patch": "rootL", "at": "u0", "range": RANGE_TOP},
    {"patch": "rear1", "at": "u0", "range": [0, PI], "reverse": True},
    {"patch": "rootR", "at": "u0", "range": RANGE_TOP, "reverse": True},
]})
patches.append({"name": "mid_bottom", "kind": "fill", "height": MID_HEIGHT, "borders": [
    {"patch": "front2", "at": "u1", "range": [PI, "2*pi"]},
    {"patch": "rootR", "at": "u0", "range": RANGE_BOTTOM, "reverse": True},
    {"patch": "rear1", "at": "u0", "range": [PI, "2*pi"], "reverse": True},
    {"patch": "rootL", "at": "u0", "range": RANGE_BOTTOM},
]})

# --- rear fuselage ---------------------------------------------------------------------------
# rear1 tapers and rises from the circle R at x2 to the circle tail_r R (centre raised by
# tail_lift R) at x3, ending with a purely axial tangent; rear2 starts at the same circle at x4.
L3 = X2 - X3
L4 = X4 - X_TAIL
TAIL_SECTION = ("tail_r*R", "tail_lift*R")
patches.append(pde("rear1", boundary=typed(
    u0=(circle_section(X2, "R"), (f"{-L3}", "0", "0")),
    u1=(circle_section(X3, *TAIL_SECTION), (f"{-L3}", "0", "0")))))

# --- the stabilisers: the same construction as the wings, on the tail section x3..x4 -------
STAB_RIM = (X3, X4, "tail_r*R", "tail_lift*R", "stab_h", "stab_lam", "stab_p")
patches.append(root_blend("stabRootL", -1, "stabL", *STAB_RIM))
patches.append(root_blend("stabRootR", +1, "stabR", *STAB_RIM))
patches.append(stabiliser("stabL", -1))
patches.append(stabiliser("stabR", +1))
patches.append({"name": "stabTipL", "kind": "fill", "borders": [{"patch": "stabL", "at": "t1"}], "height": 0.3})
patches.append({"name": "stabTipR", "kind": "fill", "borders": [{"patch": "stabR", "at": "t1"}], "height": 0.3})
patches.append({"name": "tail_top", "kind": "fill", "height": TAIL_HEIGHT, "borders": [
    {"patch": "rear1", "at": "u1", "range": [0, PI]},
    {"patch": "stabRootL", "at": "u0", "range": RANGE_TOP},
    {"patch": "rear2", "at": "u0", "range": [0, PI], "reverse": True},
    {"patch": "stabRootR", "at": "u0", "range": RANGE_TOP, "reverse": True},
]})
patches.append({"name": "tail_bottom", "kind": "fill", "height": TAIL_HEIGHT, "borders": [
    {"patch": "rear1", "at": "u1", "range": [PI, "2*pi"]},
    {"patch": "stabRootR", "at": "u0", "range": RANGE_BOTTOM, "reverse": True},
    {"patch": "rear2", "at": "u0", "range": [PI, "2*pi"], "reverse": True},
    {"patch": "stabRootL", "at": "u0", "range": RANGE_BOTTOM},
]})

# rear2's end is the tail tip as before the tail was added (axial pull 1.2): the cap 'tail' is unchanged.
TIP_PULL = 1.2
patches.append(pde("rear2", boundary=typed(
    u0=(circle_section(X4, *TAIL_SECTION), (f"{-L4}", "0", "0")),
    u1=(circle_section(X_TAIL, "tip_r*R", "tip_lift*R"), (f"{-TIP_PULL}", "-0.3*R*cos(v)", "-0.3*R*sin(v)")))))
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
    "Seed 000 Fig. 8d: an aeroplane assembled from 22 patches. Axis x (nose at +x), z up. "
    "Fuselage (10): 'front1' (fourth-order PDE) runs from a small nose section to a circle of radius R; 'front2' "
    "continues its end u1 (chained: G1) to a circle R at x1 with a purely axial tangent; 'nose' is a fill closing "
    "front1 (G1). 'rear1' runs from a circle R at x2 (purely axial) to a smaller raised circle (tail_r, tail_lift) "
    "at x3 (purely axial); 'rear2' runs from that circle at x4 (purely axial) to a small tail section closed by "
    "the fill 'tail'. "
    "Wings (6): 'rootL'/'rootR' are fourth-order PDE blends from a lens-shaped rim in the side plane y = -R / +R "
    "(x from x1 to x2 and back, z = h R sin phi, pointed tips), leaving it inside that plane (lam), to the root "
    "border t = 0 of the surfaces 'wingL'/'wingR' by reference (tangency, re-derived when a wing moves: wing_x, "
    "sweep, dihedral, gap, chord, thick): tapered, swept, airfoil-like; the fills 'tipL'/'tipR' close their tips "
    "(height 0.3: round). Between x1 and x2 the fuselage is two four-sided fills, 'mid_top'/'mid_bottom', each over "
    "half of front2's end circle, half of each rim and half of rear1's start circle, G1 to all four (the axial "
    "tangents make the four tangent planes agree at the rims' tips). "
    "Tail (6): the horizontal stabilisers are built the same way on the section x3..x4: 'stabRootL'/'stabRootR' "
    "blend from a lens in the plane y = -+tail_r R (half-height stab_h, stab_lam) to the root of the stabiliser "
    "surfaces 'stabL'/'stabR' by reference (stab_x moves them; stab_sweep, stab_dihedral, stab_gap, stab_chord, "
    "stab_thick), closed by 'stabTipL'/'stabTipR' (height 0.3); 'tail_top'/'tail_bottom' are the four-sided fills "
    "between rear1's end circle, the two rims and rear2's start circle. "
    "Every join is certified G1 by pdesurf check. pdesurf's construction: the paper gives no data for this figure."
)

with open(OUT, "w") as f:
    json.dump(scene, f, indent=2, ensure_ascii=False)
    f.write("\n")
print(OUT)
