#!/usr/bin/env python3
"""Writes tests/hostile/scenes/*.json and scenes.json: hostile scenes, each with the named
error both the CLI and the wasm module must give (tests/js/hostile.test.mjs): `export` to OBJ
and a solve, or (command "check") `pdesurf check` and a solve with the join report, or (command
"cad") `export -o x.step` and the module's exportCad. Deterministic:
run again after adding a case.   python3 tests/hostile/make-scenes.py"""
import copy, json, os

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, '..', '..')
load = lambda p: json.load(open(os.path.join(ROOT, p)))
vase = load('examples/zhang-vase-fig2a.json')
v1 = load('tests/fixtures/v1/you2004-fig2a.json')
bez = load('examples/wu2015-fig1a.json')

def with_(base, f):
    d = copy.deepcopy(base); f(d); return d

def set_boundary_x(d):
    d['patches'][0]['boundary']['x']['u0'] = ['1e+200*cos(a1*v)']

def v1_coef(d):
    d['patches'][0]['boundary']['x']['u0'][0][0]['coef'] = 1e200

def bezier_patch(d):
    return [p for p in d['patches'] if p['kind'] == 'bezier'][0]

def wrap_degree(d):
    bezier_patch(d)['normals']['degree'] = [4294967297, 1]

# cpp/common/limits.hpp: kBezierAssembly bounds Nu*Nv*(m+1)^2 + Nu*K^2 summed over a scene's
# Bezier patches. One patch of degree 16 with a 256 x 256 field is within it (the degree and
# grid caps keep every single patch within it); one more such patch than fits is not.
BEZIER_ASSEMBLY = 2 ** 29
def big_assembly(d):
    p = bezier_patch(d)
    n = 16
    p['degree'] = [n, n]
    p['control_net'] = [[i / n, j / n, 0] for i in range(n + 1) for j in range(n + 1)]
    p['normals'] = {'grid': [256, 256], 'field': {'x': '0', 'y': '0', 'z': '1'}}
    per_patch = 257 * 257 * (n + 1) ** 2 + 257 * ((n + 1) ** 2) ** 2
    d['patches'] = [dict(copy.deepcopy(p), name=f'surface{k}') for k in range(BEZIER_ASSEMBLY // per_patch + 1)]

def many_patches(d):
    base = d['patches'][0]
    d['patches'] = [dict(copy.deepcopy(base), name=f'blend{k}') for k in range(64)]

fig4 = load('examples/wu2015-fig4.json')
BIG_EXPRESSION = '+'.join(['v'] * 11000)  # 22 KB

def set_label(d, text):
    next(iter(d['parameters'].values()))['label'] = text

def fig4_range_past_border(d):
    d['patches'][1]['meets']['v_range'] = [0.5, 2.5]

def hex_number(d):
    d['patches'][0]['boundary']['z']['u0'] = ['0x10']

fig4a = load('examples/you2004-fig4a.json')
def gap_hidden_by_far_patch(d):
    d['patches'][2]['z'] = '0.5'  # the plane half a unit above the blend's end
    d['patches'].append({'name': 'far', 'kind': 'surface', 'v_range': [0, '2*pi'], 't_range': [0, 1],
                         'x': 'cos(v)', 'y': 'sin(v)', 'z': '1e10 + t'})

bottle = load('examples/bottle-solid.json')
fillet = load('examples/ref-sphere-fillet.json')
def far_plane(d):
    d['version'] = 4
    d['patches'][1]['placement'] = {'translate': [1e16, 0, 0]}
def chain_both_ends_one_edge(d):
    d['patches'].append({'name': 'sheet', 'kind': 'pde', 'v_range': [0, '2*pi'],
                         'ends': {'u0': {'patch': 'shoulder', 'at': 'u1'}, 'u1': {'patch': 'shoulder', 'at': 'u1'}}})
def chain_v_range_one_ulp(d):
    d['patches'].append({'name': 'sheet', 'kind': 'pde', 'v_range': [0, 6.283185307179587],  # 2*pi is ...586
                         'ends': {'u0': {'patch': 'shoulder', 'at': 'u1'}, 'u1': {'surface': 'neck', 'at': 't1'}}})

def heavy_tube_fill(parts):
    # A tube whose x and y are ~900-character products (37 wavy factors), a fill of `parts`
    # ranges of its bottom ring.
    import math
    def product(base):
        return base + '*' + '*'.join(f'(1+0.001*sin({k}*v+{k}*t))' for k in range(1, 38))
    tube = {'name': 'tube', 'kind': 'surface', 't_range': [0, 1], 'v_range': [0, '2*pi'], 'x': product('cos(v)'), 'y': product('sin(v)'), 'z': 't'}
    borders = [{'patch': 'tube', 'at': 't0', 'range': [2 * math.pi * k / parts, 2 * math.pi * (k + 1) / parts]} for k in range(parts)]
    return {'format': 'pdesurf-scene', 'version': 4, 'patches': [tube, {'name': 'cap', 'kind': 'fill', 'borders': borders}]}

strips = load('examples/fill-four-strips.json')
def strips_blend_on_fill_border(d):
    d['patches'].append({'name': 'blend', 'kind': 'pde', 'v_range': [-0.5, 0.5],
                         'ends': {'u0': {'surface': 'west', 'at': 't0'}, 'u1': {'surface': 'east', 'at': 't0'}}})
def strips_two_fills(d):
    second = copy.deepcopy(d['patches'][0]); second['name'] = 'fill2'; d['patches'].insert(1, second)
def two_chains_one_edge(d):
    d['patches'].append({'name': 'sheet', 'kind': 'pde', 'v_range': [0, '2*pi'], 'ends': {'u0': {'patch': 'shoulder', 'at': 'u1'}, 'u1': {'surface': 'neck', 'at': 't1'}}})
    d['patches'].append({'name': 'sheet2', 'kind': 'pde', 'v_range': [0, '2*pi'], 'ends': {'u0': {'patch': 'shoulder', 'at': 'u1'}, 'u1': {'surface': 'neck', 'at': 't1'}}})

def bezier_heavy_fields(d):
    heavy = '+'.join(f'sin({k}*u+v)*exp({k}*v-u)' for k in range(1, 41))
    p = bezier_patch(d)
    p['normals'] = {'grid': [256, 256], 'field': {'x': heavy, 'y': heavy + '+1', 'z': heavy + '+2'}}
    second = copy.deepcopy(p); second['name'] = p['name'] + '2'
    d['patches'].append(second)

def bezier_net_at(points):
    def f(d):
        p = bezier_patch(d)
        p['lambda'] = 0
        p['control_net'] = [points(k) for k in range(len(p['control_net']))]
    return f

def plate_chain(v_range):
    import math
    net = [[j * 0.25, i * 0.25, 0.3 * math.sin(i * 0.7) * math.cos(j * 0.9)] for i in range(5) for j in range(5)]
    plate = {'name': 'plate', 'kind': 'bezier', 'energy': 'thin-plate', 'degree': [4, 4], 'control_net': net, 'lambda': 0, 'gamma': 0}
    ext = {'name': 'ext', 'kind': 'pde', 'v_range': v_range, 'ends': {'u0': {'patch': 'plate', 'at': 'u1', 'continuity': 'tangency'}},
           'boundary': {'x': {'u1': ['v', 0]}, 'y': {'u1': [2, 1]}, 'z': {'u1': [0.2, 0]}}}
    return {'format': 'pdesurf-scene', 'version': 4, 'patches': [ext, plate]}

# Cases measured by the CAD export: `export -o x.step` in the CLI, exportCad in the module.
cad = [
    ('cad-heavy-fill', heavy_tube_fill(3), 16, 'TooLarge', 'the CAD fit of the scene would need more than 1e+10 units of work',
     'issue 38 #3: a fill of a heavy tube took 398 s natively to export as STEP (its derivative bounds halving their intervals); no scene budget'),
]

# Cases measured by the join certificate: `check` in the CLI, a solve with joins in the module.
checked = [
    ('gap-hidden-by-far-patch', with_(fig4a, gap_hidden_by_far_patch), 16, 'InvalidField', "is not the border u1 of 'blend': they are 0.5 apart",
     'issue 38 #6: a 0.5 gap passed as G0 5e-11 once a patch at z = 1e10 grew the scene (tolerances were the whole scene\'s)'),
]

# Issue 40: a "surface" given as NURBS.
def nurbs_scene(edit):
    n = {'degree': [1, 1], 'knots': [[0, 0, 1, 1], [0, 0, 1, 1]], 'points': [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0.2]]]}
    edit(n)
    return {'format': 'pdesurf-scene', 'version': 4, 'patches': [{'name': 'sheet', 'kind': 'surface', 'nurbs': n}]}

def dense_nurbs(n):
    n['degree'] = [3, 3]
    n['points'] = [[[i, j, 0] for j in range(129)] for i in range(129)]
    k = [0, 0, 0, 0] + list(range(1, 126)) + [126, 126, 126, 126]
    n['knots'] = [k, k]

def heavy_nurbs(n):
    n['degree'] = [25, 25]
    n['points'] = [[[i, j, 0] for j in range(64)] for i in range(64)]
    k = [0] * 26 + list(range(1, 39)) + [39] * 26
    n['knots'] = [k, k]

def nurbs_domain(lo, hi):
    def edit(n):
        n['knots'] = [[lo, lo, hi, hi], [0, 0, 1, 1]]
    return edit

cases = [
    # file, scene (dict or raw text), grid, code, message substring, why
    ('float-overflow', with_(vase, set_boundary_x), 16, 'NonFinite', 'beyond what a float holds',
     'a boundary 1e+200 cos(v): finite in double, not in the float mesh (was written as "v inf 0 0")'),
    ('v1-coefficient-1e200', with_(v1, v1_coef), 16, 'NonFinite', 'beyond what a float holds',
     'a version-1 coefficient of 1e200: the float mesh held inf and NaN normals'),
    ('newline-in-title', with_(vase, lambda d: d.__setitem__('title', 'a\nv 1 2 3')), 16, 'InvalidField', 'title',
     'a newline would start a line of its own in the OBJ file'),
    ('newline-in-patch-name', with_(vase, lambda d: d['patches'][0].__setitem__('name', 'x\nv 1 2 3\no y')), 16, 'InvalidField', 'name',
     'a patch name is written as an OBJ "o" line'),
    ('bezier-degree-wraps', with_(bez, wrap_degree), 16, 'InvalidField', 'degree[0]',
     'an integer above INT_MAX (was read as 1)'),
    ('bezier-assembly', json.dumps(with_(bez, big_assembly)), 16, 'TooLarge', 'assembly work',
     '14 patches of degree 16 with 257 x 257 normal fields: each alone is accepted (~0.1 s natively), together over the scene\'s assembly cap'),
    ('64-patches-1024', with_(vase, many_patches), 1024, 'TooLarge', 'vertices',
     '64 patches at 1024 x 1024: each within its cap, 67 M vertices together'),
    ('hex-number', with_(vase, hex_number), 16, 'ParseError', 'decimal',
     '0x10 was read as 16 by strtod, undocumented'),
    ('duplicate-key', json.dumps(vase).replace('"version": 2', '"version": 2, "version": 2'), 16, 'ParseError', 'twice',
     'the last of two equal keys won silently'),
    ('nel-in-title', with_(vase, lambda d: d.__setitem__('title', 'a\u0085v 1 2 3')), 16, 'InvalidField', 'title: a control character U+0085',
     'NEL (U+0085) is a line break to some OBJ readers: the title is the OBJ comment line'),
    ('line-separator-in-patch-name', with_(vase, lambda d: d['patches'][0].__setitem__('name', 'x\u2028v 1 2 3\u2028o y')), 16, 'InvalidField', 'U+2028',
     'U+2028 splits lines for some readers: the name is an OBJ "o" line'),
    ('paragraph-separator-in-label', with_(vase, lambda d: set_label(d, 'r\u2029v 1 2 3')), 16, 'InvalidField', 'U+2029',
     'U+2029 in a parameter label (one line)'),
    ('c1-csi-in-patch-name', with_(vase, lambda d: d['patches'][0].__setitem__('name', 'x\u009b31m')), 16, 'InvalidField', 'U+009B',
     'a C1 control (CSI) in a patch name'),
    ('expression-22kb', with_(vase, lambda d: d['patches'][0]['boundary']['x']['u0'].__setitem__(0, BIG_EXPRESSION)), 16, 'TooLarge',
     'longer than 1000 characters', 'a 22 KB expression: a size limit, named in a short message'),
    ('expression-22kb-in-number', with_(vase, lambda d: d['patches'][0]['v_range'].__setitem__(1, BIG_EXPRESSION)), 16, 'TooLarge',
     'longer than 1000 characters', 'a 22 KB expression where a number goes (was ParseError from the parser)'),
    ('bezier-join-past-border', with_(fig4, fig4_range_past_border), 16, 'InvalidField', 'is not inside the v_range [-1.5, 1.5]',
     "a Bezier border mapped onto v in [0.5, 2.5] of a strip drawn over [-1.5, 1.5]: was certified as a passing join"),
    ('deep-1000', '{"format": ' + '[' * 1000 + ']' * 1000 + '}', 16, 'TooLarge', 'nested deeper',
     '1,000 nested arrays'),
    ('placement-far-1e16', with_(fillet, far_plane), 16, 'InvalidField', "1e+16 is 1.1e+15 times the surface's size",
     'issue 38 #7: the plane placed at x = 1e16 put the fillet\'s ring 1.4 off its circle, written with exit 0 and certified'),
    ('placement-translate-1e300', with_(bottle, lambda d: d['patches'][0].__setitem__('placement', {'translate': [1e300, 0, 0]})), 16, 'InvalidField',
     'patches[0].placement.translate: 1e+300 is', 'issue 38 #12: check said the loop encloses no area, sample printed 1e300s with exit 0'),
    ('chain-power-1e300', with_(bottle, lambda d: d['patches'].append({'name': 'sheet', 'kind': 'pde', 'v_range': [0, '2*pi'],
     'ends': {'u0': {'patch': 'shoulder', 'at': 'u1', 'power': 1e300}, 'u1': {'surface': 'neck', 'at': 't1'}}})), 16, 'InvalidField',
     'patches[5].ends.u0.power: at most 100', 'issue 38 #12: check said "0.8 apart", export NonFinite; p squared overflowed'),
    ('fill-centre-1e300', with_(bottle, lambda d: d['patches'][4].__setitem__('centre', [0, 0, 1e300])), 16, 'InvalidField',
     "patches[4].centre: is 2.63e+300 loop radii", 'issue 38 messages: a centre of 1e300 was reported as "the fill folds"'),
    ('fill-power-1e300', with_(bottle, lambda d: d['patches'][4]['borders'][0].__setitem__('power', 1e300)), 16, 'InvalidField',
     'patches[4].borders[0].power: at most 100', 'issue 38 messages: a border power of 1e300 was reported as "does not turn around"'),
    ('trimline-narrow-pole', with_(fillet, lambda d: d['patches'][0]['ends']['u0'].__setitem__('at', {'t': '0.5 + 1e-9/(v - 2*pi/3)'})), 6,
     'InvalidField', "patches[0].ends.u0.at: the trimline t = ", 'issue 38 #15: a pole of tau too narrow for the samples was accepted on an 8x8 grid and NonFinite, naming no end, on 4x6'),
    ('chain-both-ends-one-edge', with_(bottle, chain_both_ends_one_edge), 16, 'InvalidField', 'would start and end on the same edge',
     'issue 38 #11: both ends of one patch continuing u1 of the shoulder (three sheets on one edge) were accepted'),
    ('bezier-field-sampling', with_(bez, bezier_heavy_fields), 16, 'TooLarge', "patches[1].normals.field.z: sampling",
     "issue 38 re-attack: normal fields typed as 1 KB expressions on 256x256 grids were sampled point by point without a budget (64 patches: 34 s, also from a 5 KB link)"),
    ('bezier-net-at-a-point', with_(bez, bezier_net_at(lambda k: [1, 1, 1])), 16, 'InvalidField', 'the surface has no area',
     'issue 38 re-attack: a net of 25 equal points was written to STEP as a closed solid of volume 5e-34; check failed on a "crossing" of rounding'),
    ('bezier-net-on-a-line', with_(bez, bezier_net_at(lambda k: [0.1 * k, 0, 0])), 16, 'InvalidField', 'the surface has no area',
     'issue 38 re-attack: a net on the x-axis was certified ("area 0 ... ok") and exported as a face with zero normals'),
    ('bezier-normals-1e200', with_(bez, lambda d: bezier_patch(d)['normals'].__setitem__('vectors', [[float(x) * 1e200 for x in v] for v in bezier_patch(d)['normals']['vectors']])),
     16, 'NonFinite', 'lambda times its length squared is not finite',
     'issue 38 re-attack: continuous normals 1e200 long were reported as a singular energy ("reduce lambda or gamma, or the degree")'),
    ('placement-scale-1e-150', with_(strips, lambda d: [p.__setitem__('placement', {'scale': 1e-150}) for p in d['patches'] if p['kind'] == 'surface']),
     16, 'InvalidField', 'placement.scale: a scale of 1e-150 is outside 1e-12 .. 1e12',
     'issue 38 re-attack: every strip scaled by 1e-150 was blamed as "dS/dt is parallel to the trimline" (an underflow), and drew at 0'),
    ('chain-on-bezier-v-range-1e308', plate_chain([-1e308, 1e308]), 16, 'NonFinite', "patch 'ext': component x",
     'issue 38 re-attack: a chain on a Bezier border over v in +-1e308: export named no patch (the module did)'),
    ('three-sheets-blend-on-bezier-border', with_(strips, strips_blend_on_fill_border), 16, 'InvalidField',
     "patches[9].ends.u0: edge t0 of 'west' is already met by patches[0].borders.u0 ('fill')",
     'issue 38 re-attack: a blend and a Bezier fill on one strip border (two surfaces in one hole, three sheets on an edge) were both certified'),
    ('three-sheets-two-bezier-fills', with_(strips, strips_two_fills), 16, 'InvalidField', 'three sheets would meet along it',
     'issue 38 re-attack: two Bezier fills of one hole: all 8 joins certified, the second fill a body of its own'),
    ('three-sheets-two-chains', with_(bottle, two_chains_one_edge), 16, 'InvalidField', 'is already met by patches[5].ends',
     'issue 38 re-attack: two patches continuing one edge (each alone fine) were both certified'),
    ('chain-v-range-one-ulp', with_(bottle, chain_v_range_one_ulp), 16, 'InvalidField', '6.2831853071795871] differs from',
     'issue 38 messages: a v_range one ulp off 2*pi was "[0, 6.28319] differs from [0, 6.28319]"'),
    ('nurbs-degree-26', nurbs_scene(lambda n: n.__setitem__('degree', [26, 1])), 16, 'InvalidField', 'patches[0].nurbs.degree[0]: expected an integer in 1..25',
     'issue 40: an absurd degree, refused before any knot is read'),
    ('nurbs-129x129-points', nurbs_scene(dense_nurbs), 16, 'TooLarge', 'patches[0].nurbs.points: 129 × 129 control points: at most 16384',
     'issue 40: more control points than a surface may have, counted before they are read'),
    ('nurbs-degree-25-64-rows', nurbs_scene(heavy_nurbs), 16, 'TooLarge', 'patches[0].nurbs: one evaluation would take',
     'issue 40: degree 25 over 64 rows, an evaluation of ~200 000 de Boor steps per sample: hours on the largest grid'),
    ('nurbs-knots-decreasing', nurbs_scene(lambda n: n['knots'].__setitem__(1, [0, 1, 0, 1])), 16, 'InvalidField', 'patches[0].nurbs.knots[1]: knot 2 is smaller than the one before',
     'issue 40: a knot vector that goes back'),
    ('nurbs-weight-zero', nurbs_scene(lambda n: n.__setitem__('weights', [[1, 1], [1, 0]])), 16, 'InvalidField', 'patches[0].nurbs.weights[1][1]: a weight must be positive',
     'issue 40: a zero weight (a pole at infinity)'),
    ('nurbs-pole-text', nurbs_scene(lambda n: n['points'][1][0].__setitem__(2, 'nan')), 16, 'InvalidField', 'patches[0].nurbs.points[1][0][2]: expected a number',
     'issue 40: a pole coordinate given as text'),
    ('nurbs-poles-1e300', nurbs_scene(lambda n: n.__setitem__('points', [[[x * 1e300 for x in p] for p in row] for row in n['points']])), 16, 'NonFinite', "patch 'sheet'",
     'issue 40: poles whose products overflow'),
    ('nurbs-domain-1e-300', nurbs_scene(nurbs_domain(0, 1e-300)), 16, 'NonFinite', "patch 'sheet'",
     'issue 40: a knot span of 1e-300, whose derivatives overflow'),
]

os.makedirs(os.path.join(HERE, 'scenes'), exist_ok=True)
manifest = {'format': 'pdesurf-hostile-scenes', 'version': 1, 'scenes': []}
for command, group in (('export', cases), ('check', checked), ('cad', cad)):
    for name, scene, grid, code, message, why in group:
        text = scene if isinstance(scene, str) else json.dumps(scene, indent=1)
        with open(os.path.join(HERE, 'scenes', name + '.json'), 'w') as f:
            f.write(text + '\n')
        manifest['scenes'].append({'name': name, 'file': f'scenes/{name}.json', 'command': command, 'grid': grid, 'code': code,
                                   'message': message, 'why': why})
with open(os.path.join(HERE, 'scenes.json'), 'w') as f:
    f.write(json.dumps(manifest, indent=2, ensure_ascii=False) + '\n')
print(len(cases) + len(checked) + len(cad), 'scenes written')
