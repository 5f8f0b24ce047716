"""A small, self-contained reader for FOSSSim scenes and trajectory files (the '-o' output).

Written for the oracle checks (check.py) so that they depend on nothing but the standard library
and on nothing in the simulator: the scene is read with xml.etree and the file layout is the one of
the compatibility spec, section 6:

  per record, little-endian, no header:
    x: 2N float64, v: 2N float64
    if the scene has a collision handler (simple, continuous-time, hybrid; not penalty):
      int32 count, then per impulse int32 type (PP=0, PE=1, PH=2), int32 i, int32 j,
      float64 nx, ny, tau
    if the handler is continuous-time or hybrid:
      int32 count, then per polynomial int32 length and that many float64
  Record 0 is the initial state; continuous-time and hybrid write a mid-step record (from inside
  collision handling) and an end-of-step record per step, the other scenes one record per step.
"""
import math
import struct
import xml.etree.ElementTree as ET

PP, PE, PH = 0, 1, 2


class Scene:
    """The parts of a scene file that the checks need, with defaults from the spec, section 1."""

    def __init__(self, path):
        root = ET.parse(path).getroot()
        assert root.tag == 'scene', path
        self.path = path
        num = lambda e, a, d=None: float(e.get(a)) if e.get(a) is not None else d
        first = lambda tag: root.find(tag)
        self.description = first('description').get('text') if first('description') is not None else ''
        self.duration = num(first('duration'), 'time')
        integ = first('integrator')
        self.integrator = integ.get('type')
        self.dt = num(integ, 'dt')
        self.num_steps = math.ceil(self.duration / self.dt)
        self.m, self.x0, self.v0, self.fixed, self.r = [], [], [], [], []
        for p in root.findall('particle'):
            self.m.append(num(p, 'm'))
            self.x0.append((num(p, 'px'), num(p, 'py')))
            self.v0.append((num(p, 'vx'), num(p, 'vy')))
            self.fixed.append(p.get('fixed').strip() == '1')
            self.r.append(num(p, 'radius', 0.1))
        self.n = len(self.m)
        self.edges = [(int(e.get('i')), int(e.get('j')), num(e, 'radius', 0.015)) for e in root.findall('edge')]
        self.halfplanes = [((num(h, 'px'), num(h, 'py')), (num(h, 'nx'), num(h, 'ny'))) for h in root.findall('halfplane')]
        self.springs = [(int(s.get('edge')), num(s, 'k'), num(s, 'l0'), num(s, 'b', 0.0)) for s in root.findall('springforce')]
        self.gravity = [(num(g, 'fx'), num(g, 'fy')) for g in root.findall('simplegravity')]
        self.constant = [(num(g, 'fx'), num(g, 'fy')) for g in root.findall('constantforce')]
        self.drag = [num(d, 'b') for d in root.findall('dragdamping')]
        self.gravitational = [(int(g.get('i')), int(g.get('j')), num(g, 'G')) for g in root.findall('gravitationalforce')]
        self.vortex = [(int(g.get('i')), int(g.get('j')), num(g, 'kbs'), num(g, 'kvc')) for g in root.findall('vortexforce')]
        c = first('collision')
        self.collision = c.get('type') if c is not None else 'none'
        self.cor = num(c, 'COR', 1.0) if c is not None else 1.0
        self.maxiters = int(num(c, 'maxiters', 10.0)) if c is not None else 0
        default_k = {'penalty': 100.0, 'hybrid': 10.0}.get(self.collision, 0.0)
        default_t = {'penalty': 0.01, 'hybrid': 0.1}.get(self.collision, 0.0)
        self.penalty_k = num(c, 'k', default_k) if c is not None else 0.0
        self.penalty_thickness = num(c, 'thickness', default_t) if c is not None else 0.0

    @property
    def has_impulses(self):
        return self.collision in ('simple', 'continuous-time', 'hybrid')

    @property
    def has_polynomials(self):
        return self.collision in ('continuous-time', 'hybrid')


class Record:
    __slots__ = ('x', 'v', 'impulses', 'polys')

    def __init__(self, x, v, impulses, polys):
        self.x, self.v, self.impulses, self.polys = x, v, impulses, polys

    def pos(self, i):
        return (self.x[2 * i], self.x[2 * i + 1])

    def vel(self, i):
        return (self.v[2 * i], self.v[2 * i + 1])


def read_records(path, scene):
    """Every record of the file, checking that it parses exactly to its end."""
    data = open(path, 'rb').read()
    n, off, out = scene.n, 0, []
    while off < len(data):
        x = struct.unpack_from('<%dd' % (2 * n), data, off); off += 16 * n
        v = struct.unpack_from('<%dd' % (2 * n), data, off); off += 16 * n
        impulses, polys = [], []
        if scene.has_impulses:
            (count,) = struct.unpack_from('<i', data, off); off += 4
            assert 0 <= count < 10 ** 6, 'bad impulse count %d' % count
            for _ in range(count):
                kind, i, j = struct.unpack_from('<3i', data, off); off += 12
                nx, ny, tau = struct.unpack_from('<3d', data, off); off += 24
                impulses.append((kind, i, j, (nx, ny), tau))
        if scene.has_polynomials:
            (count,) = struct.unpack_from('<i', data, off); off += 4
            assert 0 <= count < 10 ** 7, 'bad polynomial count %d' % count
            for _ in range(count):
                (k,) = struct.unpack_from('<i', data, off); off += 4
                polys.append(struct.unpack_from('<%dd' % k, data, off)); off += 8 * k
        out.append(Record(x, v, impulses, polys))
    assert off == len(data), '%s: trailing bytes' % path
    return out


class Trajectory:
    """A scene's trajectory: `ends` holds record 0 and every end-of-step record (index = step
    number), `mids` the mid-step records of continuous-time and hybrid scenes (mids[k] belongs to
    step k + 1, i.e. lies between ends[k] and ends[k + 1])."""

    def __init__(self, path, scene):
        self.scene = scene
        recs = read_records(path, scene)
        if scene.has_polynomials:
            assert len(recs) == 1 + 2 * scene.num_steps, '%d records, expected %d' % (len(recs), 1 + 2 * scene.num_steps)
            self.ends = [recs[0]] + recs[2::2]
            self.mids = recs[1::2]
        else:
            assert len(recs) == 1 + scene.num_steps, '%d records, expected %d' % (len(recs), 1 + scene.num_steps)
            self.ends = recs
            self.mids = []


# ---- small vector helpers ------------------------------------------------------------------------

def add(a, b): return (a[0] + b[0], a[1] + b[1])
def sub(a, b): return (a[0] - b[0], a[1] - b[1])
def mul(s, a): return (s * a[0], s * a[1])
def dot(a, b): return a[0] * b[0] + a[1] * b[1]
def cross(a, b): return a[0] * b[1] - a[1] * b[0]
def norm(a): return math.hypot(a[0], a[1])
def unit(a): return mul(1.0 / norm(a), a)


def segment_distance(p, a, b):
    """Distance from point p to the segment a-b."""
    e = sub(b, a)
    ee = dot(e, e)
    t = 0.0 if ee == 0 else max(0.0, min(1.0, dot(sub(p, a), e) / ee))
    return norm(sub(p, add(a, mul(t, e))))
