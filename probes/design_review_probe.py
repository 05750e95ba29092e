#!/usr/bin/env python3
"""Design-review probe for hdcad starter housings (independent of hdcad's source).

    python probe.py OUTDIR... [--no-oil] [--json FILE] [--catalog DIR] [--quick]

OUTDIR is a model folder written by `hdcad design` (it holds one STEP per part, assembly.step,
results.json, optionally review_assembly.step), or a folder holding such model folders.

Everything is measured from the STEP geometry (B-rep faces, exact ray casting with OCCT,
boolean common volumes, planar sections).  results.json is read only for the model code
(family / size), the material name (density) and the lubricant (whether an oil check applies).
Part and body names from the STEP files are printed for the reader but never used to decide
what a body is: bearings, seals, screws, O-rings ... are recognised from their dimensions.

Catalog tables (read-only) come from <project>/catalog/*.csv (ISO 15 bearings, DIN 5418
abutments, DIN 471/472 rings, ISO 261 threads, DIN 908 ports, ISO 3601 glands, ISO 6194 seals,
ISO 4762 heads, ISO 273 clearance holes, FD tables 311-1/312-1/315-1).
"""
import argparse
import csv
import glob
import json
import math
import os
import re
import sys
import time
from collections import defaultdict

import numpy as np

from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve, BRepAdaptor_Curve2d, BRepAdaptor_Surface
from OCP.BRepAlgoAPI import BRepAlgoAPI_Common
from OCP.BRepBndLib import BRepBndLib
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeFace
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRepGProp import BRepGProp
from OCP.BRepLProp import BRepLProp_SLProps
from OCP.BRepMesh import BRepMesh_IncrementalMesh
from OCP.BRepTools import BRepTools
from OCP.Bnd import Bnd_Box
from OCP.GCPnts import GCPnts_AbscissaPoint
from OCP.GProp import GProp_GProps
from OCP.GeomAbs import (GeomAbs_Cone, GeomAbs_Cylinder, GeomAbs_Plane, GeomAbs_Sphere,
                         GeomAbs_Torus)
from OCP.IFSelect import IFSelect_RetDone
from OCP.IntCurvesFace import IntCurvesFace_ShapeIntersector
from OCP.STEPCAFControl import STEPCAFControl_Reader
from OCP.STEPControl import STEPControl_Reader
from OCP.TCollection import TCollection_ExtendedString
from OCP.TDF import TDF_LabelSequence
from OCP.TDataStd import TDataStd_Name
from OCP.TDocStd import TDocStd_Document
from OCP.TopAbs import (TopAbs_EDGE, TopAbs_FACE, TopAbs_REVERSED, TopAbs_SHELL,
                        TopAbs_SOLID)
from OCP.TopExp import TopExp, TopExp_Explorer
from OCP.TopLoc import TopLoc_Location
from OCP.TopTools import (TopTools_IndexedDataMapOfShapeListOfShape,
                          TopTools_IndexedMapOfShape)
from OCP.TopoDS import TopoDS
from OCP.XCAFDoc import XCAFDoc_DocumentTool
from OCP.gp import gp_Ax3, gp_Dir, gp_Lin, gp_Pln, gp_Pnt

CATALOG_DEFAULT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "catalog")
DENSITY = {"steel": 7.85, "aluminium": 2.70, "aluminum": 2.70, "cast_iron": 7.20}  # g/cm3
WALL_MIN = {"steel": 3.0, "aluminium": 4.0, "aluminum": 4.0, "cast_iron": 5.0}  # HOUSING_RULES §4
ENGAGE_K = {"steel": 1.0, "aluminium": 2.0, "aluminum": 2.0, "cast_iron": 1.25}  # × d, VDI 2230 guidance
# DIN 974-1 counterbore diameters for ISO 4762 (row 1, medium clearance).  Not in the catalog
# tables: probe constant, used only to compare (finding says so).
DIN974_CB = {"M3": 6.5, "M4": 8.0, "M5": 10.0, "M6": 11.0, "M8": 15.0, "M10": 18.0, "M12": 20.0,
             "M14": 24.0, "M16": 26.0, "M20": 33.0, "M24": 40.0}

SEV_ORDER = {"blocker": 0, "major": 1, "minor": 2, "info": 3}


# ----------------------------------------------------------------------------------------------
# catalog
# ----------------------------------------------------------------------------------------------
def _read_csv(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def _f(x):
    try:
        return float(x)
    except (TypeError, ValueError):
        return None


class Catalog:
    def __init__(self, root):
        r = lambda n: _read_csv(os.path.join(root, n))
        self.bearings = [{k: (_f(v) if k != "model" else v) for k, v in row.items()}
                         for row in r("deep_groove_bearing_iso15.csv")]
        self.abut = sorted((_f(x["r_s_min_mm"]), _f(x["h_min_mm"])) for x in r("bearing_abutment_din5418.csv"))
        self.rings = [{"kind": x["kind"], "d1": _f(x["d1_mm"]), "s": _f(x["s_mm"]), "d2": _f(x["d2_mm"]),
                       "m": _f(x["m_mm"]), "n": _f(x["n_mm"])} for x in r("retaining_ring_din471_din472.csv")]
        self.threads = [{"thread": x["thread"], "d": _f(x["d_mm"]), "P": _f(x["pitch_mm"]),
                         "tap": _f(x["tap_drill_mm"]), "d3": _f(x["d3_mm"])}
                        for x in r("iso_metric_thread_iso261_iso724.csv")]
        self.ports = [{"thread": x["thread"], "d": _f(x["d_mm"]), "P": _f(x["pitch_mm"]),
                       "tap": _f(x["tap_drill_mm"]), "collar": _f(x["collar_mm"]),
                       "thread_length": _f(x["thread_length_mm"])}
                      for x in r("plug_port_din908_din7603.csv")]
        self.orings = [{"d2": _f(x["d2_mm"]), "rd": _f(x["radial_depth_mm"]), "rw": _f(x["radial_width_mm"]),
                        "fd": _f(x["face_depth_mm"]), "fw": _f(x["face_width_mm"])}
                       for x in r("oring_gland_iso3601.csv")]
        self.seals = [{"d1": _f(x["d1_mm"]), "d2": _f(x["d2_mm"]), "b": _f(x["b_mm"])}
                      for x in r("shaft_seal_iso6194.csv")]
        self.heads = {x["thread"]: {"dk": _f(x["dk_mm"]), "k": _f(x["k_mm"])} for x in r("socket_head_iso4762.csv")}
        self.clear = [{"thread": x["thread"], "fine": _f(x["fine_mm"]), "medium": _f(x["medium_mm"]),
                       "coarse": _f(x["coarse_mm"])} for x in r("clearance_hole_iso273.csv")]
        self.fd0 = {int(x["size"]): x for x in r("fd0_dimensions_311-1.csv")}
        self.fd2 = {int(x["size"]): x for x in r("fd2_dimensions_312-1.csv")}
        self.oil_A = {int(x["size"]): _f(x["A_mm"]) for x in r("fd_oil_level_315-1.csv")}

    def h_min(self, rs):
        best = None
        for r_, h in self.abut:
            if r_ <= rs + 1e-9:
                best = h
        return best if best is not None else self.abut[0][1]

    def bearing_by_D(self, D, tol=0.06):
        return [b for b in self.bearings if abs(b["D_mm"] - D) <= tol]

    def bearing_by_d(self, d, tol=0.06):
        return [b for b in self.bearings if abs(b["d_mm"] - d) <= tol]

    def bearing_by_dDB(self, d, D, B, tol=0.06):
        for b in self.bearings:
            if abs(b["d_mm"] - d) <= tol and abs(b["D_mm"] - D) <= tol and abs(b["B_mm"] - B) <= tol:
                return b
        return None

    def ring(self, kind, d1, tol=0.06):
        for x in self.rings:
            if x["kind"] == kind and abs(x["d1"] - d1) <= tol:
                return x
        return None

    def thread_by_tap(self, dia, tol=0.03):
        out = [dict(t, std="ISO 261") for t in self.threads if abs(t["tap"] - dia) <= tol]
        out += [dict(p, std="DIN 908 port") for p in self.ports if abs(p["tap"] - dia) <= tol]
        return out

    def thread_by_major(self, dia, tol=0.03):
        return [t for t in self.threads if abs(t["d"] - dia) <= tol]

    def clearance_by_dia(self, dia, tol=0.03):
        out = []
        for c in self.clear:
            for k in ("fine", "medium", "coarse"):
                if c[k] is not None and abs(c[k] - dia) <= tol:
                    out.append((c["thread"], k))
        return out

    def seal_by(self, d1=None, d2=None, b=None, tol=0.06):
        out = []
        for s in self.seals:
            if d1 is not None and abs(s["d1"] - d1) > tol:
                continue
            if d2 is not None and abs(s["d2"] - d2) > tol:
                continue
            if b is not None and abs(s["b"] - b) > tol:
                continue
            out.append(s)
        return out


# ----------------------------------------------------------------------------------------------
# findings
# ----------------------------------------------------------------------------------------------
class Findings:
    def __init__(self):
        self.rows = []
        self.measured = []  # (part, what, value) for the "measured, passes" summary

    def add(self, sev, part, finding, value, rule):
        self.rows.append({"severity": sev, "part": part, "finding": finding, "measured": value, "rule": rule})

    def ok(self, part, what, value):
        self.measured.append({"part": part, "check": what, "measured": value})


# ----------------------------------------------------------------------------------------------
# STEP reading
# ----------------------------------------------------------------------------------------------
def read_step_solids(path):
    """All solids of a STEP file as (name, TopoDS_Solid) in file coordinates; names from XCAF
    labels where present (display only)."""
    doc = TDocStd_Document(TCollection_ExtendedString("probe"))
    rd = STEPCAFControl_Reader()
    rd.SetNameMode(True)
    if rd.ReadFile(path) != IFSelect_RetDone:
        raise RuntimeError("cannot read STEP " + path)
    rd.Transfer(doc)
    st = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    labs = TDF_LabelSequence()
    st.GetFreeShapes(labs)
    out = []

    def lname(l):
        n = TDataStd_Name()
        if l.FindAttribute(TDataStd_Name.GetID_s(), n):
            try:
                return n.Get().ToExtString()
            except Exception:
                return ""
        return ""

    def walk(l, loc, prefix):
        nm = lname(l) or prefix
        if st.IsAssembly_s(l):
            ch = TDF_LabelSequence()
            st.GetComponents_s(l, ch)
            for i in range(1, ch.Length() + 1):
                c = ch.Value(i)
                cl = st.GetLocation_s(c)
                ref = c
                from OCP.TDF import TDF_Label
                rl = TDF_Label()
                if st.GetReferredShape_s(c, rl):
                    ref = rl
                cname = lname(c) or lname(ref)
                walk_ref(ref, loc.Multiplied(cl), cname)
        else:
            walk_ref(l, loc, nm)

    def walk_ref(l, loc, nm):
        if st.IsAssembly_s(l):
            walk(l, loc, nm)
            return
        shp = st.GetShape_s(l)
        if not loc.IsIdentity():
            shp = shp.Moved(loc)
        exp = TopExp_Explorer(shp, TopAbs_SOLID)
        k = 0
        while exp.More():
            out.append((nm if k == 0 else "%s#%d" % (nm, k), TopoDS.Solid_s(exp.Current())))
            k += 1
            exp.Next()
        if k == 0:
            out.append((nm + " (no solid)", None))

    for i in range(1, labs.Length() + 1):
        walk(labs.Value(i), TopLoc_Location(), lname(labs.Value(i)))
    return out


def mass_props(shape):
    g = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape, g)
    vol = g.Mass()
    c = g.CentreOfMass()
    m = g.MatrixOfInertia()
    I = np.array([[m.Value(i, j) for j in (1, 2, 3)] for i in (1, 2, 3)])
    ga = GProp_GProps()
    BRepGProp.SurfaceProperties_s(shape, ga)
    return vol, np.array([c.X(), c.Y(), c.Z()]), np.sort(np.linalg.eigvalsh(I)) if vol != 0 else np.zeros(3), ga.Mass()


def bbox(shape, gap=0.0):
    b = Bnd_Box()
    BRepBndLib.Add_s(shape, b, True)
    if b.IsVoid():
        return None
    x0, y0, z0, x1, y1, z1 = b.Get()
    return np.array([x0 - gap, y0 - gap, z0 - gap]), np.array([x1 + gap, y1 + gap, z1 + gap])


def boxes_overlap(a, b):
    return bool(np.all(a[0] <= b[1]) and np.all(b[0] <= a[1]))


def P(v):
    return gp_Pnt(float(v[0]), float(v[1]), float(v[2]))


def V(p):
    return np.array([p.X(), p.Y(), p.Z()])


def unit(v):
    n = np.linalg.norm(v)
    return v / n if n > 0 else v


def perp_basis(e):
    a = np.array([1.0, 0, 0]) if abs(e[0]) < 0.9 else np.array([0, 1.0, 0])
    x = unit(np.cross(e, a))
    y = np.cross(e, x)
    return x, y


# ----------------------------------------------------------------------------------------------
# one solid with its faces, adjacency, ray casting and feature extraction
# ----------------------------------------------------------------------------------------------
class Body:
    def __init__(self, solid, name, catalog=None):
        self.solid = solid
        self.name = name
        self.fmap = TopTools_IndexedMapOfShape()
        TopExp.MapShapes_s(solid, TopAbs_FACE, self.fmap)
        self.faces = [TopoDS.Face_s(self.fmap.FindKey(i)) for i in range(1, self.fmap.Extent() + 1)]
        self.adapt = [BRepAdaptor_Surface(f) for f in self.faces]
        self.rev = [f.Orientation() == TopAbs_REVERSED for f in self.faces]
        self.vol, self.cog, self.pm, self.area = mass_props(solid)
        self.bb = bbox(solid)
        self._ray = None
        self._adj = None
        self._info = None
        self.axis = None

    # --- basic geometry -------------------------------------------------------------------
    def fidx(self, face):
        return self.fmap.FindIndex(face) - 1

    @property
    def ray(self):
        if self._ray is None:
            self._ray = IntCurvesFace_ShapeIntersector()
            self._ray.Load(self.solid, 1e-7)
        return self._ray

    def normal(self, i, u, v):
        pr = BRepLProp_SLProps(self.adapt[i], u, v, 1, 1e-7)
        if not pr.IsNormalDefined():
            return None
        n = pr.Normal()
        n = np.array([n.X(), n.Y(), n.Z()])
        return -n if self.rev[i] else n

    def point(self, i, u, v):
        return V(self.adapt[i].Value(u, v))

    def cast(self, p, d, tmin=1e-4, tmax=1e4):
        """sorted hits (t, face index, u, v) of the ray p + t d"""
        r = self.ray
        r.Perform(gp_Lin(P(p), gp_Dir(*map(float, d))), tmin, tmax)
        hits = []
        for k in range(1, r.NbPnt() + 1):
            hits.append((r.WParameter(k), self.fidx(r.Face(k)), r.UParameter(k), r.VParameter(k)))
        hits.sort()
        return hits

    def inside(self, p):
        """point-in-solid by the orientation of the first surface crossed (two skew rays vote)."""
        votes = []
        for d in (np.array([0.5773, 0.5774, 0.5775]), np.array([-0.6003, 0.3711, -0.7084]),
                  np.array([0.1302, -0.9121, 0.3887])):
            d = unit(d)
            h = self.cast(p, d, tmin=1e-7)
            if not h:
                votes.append(False)
            else:
                t, i, u, v = h[0]
                n = self.normal(i, u, v)
                votes.append(bool(n is not None and np.dot(n, d) > 0))
            if len(votes) == 2 and votes[0] == votes[1]:
                break
        return sum(votes) * 2 > len(votes)

    @property
    def adj(self):
        if self._adj is None:
            m = TopTools_IndexedDataMapOfShapeListOfShape()
            TopExp.MapShapesAndAncestors_s(self.solid, TopAbs_EDGE, TopAbs_FACE, m)
            adj = defaultdict(set)
            self.edge_faces = []
            for k in range(1, m.Extent() + 1):
                e = TopoDS.Edge_s(m.FindKey(k))
                fl = [self.fidx(TopoDS.Face_s(f)) for f in m.FindFromIndex(k)]
                fl = sorted(set(fl))
                self.edge_faces.append((e, fl))
                for a in fl:
                    for b in fl:
                        if a != b:
                            adj[a].add(b)
            self._adj = adj
        return self._adj

    # --- face descriptions --------------------------------------------------------------------
    def face_info(self):
        if self._info is not None:
            return self._info
        info = []
        for i, (f, a) in enumerate(zip(self.faces, self.adapt)):
            t = a.GetType()
            u0, u1, v0, v1 = BRepTools.UVBounds_s(f)
            d = {"i": i, "type": {GeomAbs_Plane: "plane", GeomAbs_Cylinder: "cyl", GeomAbs_Cone: "cone",
                                  GeomAbs_Torus: "torus", GeomAbs_Sphere: "sphere"}.get(t, "other"),
                 "uv": (u0, u1, v0, v1)}
            g = GProp_GProps()
            BRepGProp.SurfaceProperties_s(f, g)
            d["area"] = g.Mass()
            um, vm = 0.5 * (u0 + u1), 0.5 * (v0 + v1)
            d["n_mid"] = self.normal(i, um, vm)
            d["p_mid"] = self.point(i, um, vm)
            if t == GeomAbs_Cylinder:
                c = a.Cylinder()
                ax = c.Axis()
                d["axis_p"] = V(ax.Location())
                d["axis_d"] = np.array([ax.Direction().X(), ax.Direction().Y(), ax.Direction().Z()])
                d["r"] = c.Radius()
                d["uspan"] = u1 - u0
                # concave (hole/bore) if the outward normal points towards the axis
                p = d["p_mid"]
                rad = p - d["axis_p"] - np.dot(p - d["axis_p"], d["axis_d"]) * d["axis_d"]
                d["concave"] = bool(d["n_mid"] is not None and np.dot(d["n_mid"], rad) < 0)
            elif t == GeomAbs_Plane:
                pl = a.Plane()
                d["normal"] = d["n_mid"]
                d["origin"] = V(pl.Location())
            elif t == GeomAbs_Cone:
                c = a.Cone()
                ax = c.Axis()
                d["axis_p"] = V(ax.Location())
                d["axis_d"] = np.array([ax.Direction().X(), ax.Direction().Y(), ax.Direction().Z()])
                d["semi"] = math.degrees(abs(c.SemiAngle()))
                d["apex"] = V(c.Apex())
            elif t == GeomAbs_Torus:
                c = a.Torus()
                ax = c.Axis()
                d["axis_p"] = V(ax.Location())
                d["axis_d"] = np.array([ax.Direction().X(), ax.Direction().Y(), ax.Direction().Z()])
                d["R"] = c.MajorRadius()
                d["r"] = c.MinorRadius()
            d["bpts"] = self.boundary_points(i)
            info.append(d)
        self._info = info
        return info

    def boundary_points(self, i, n=24):
        pts = []
        exp = TopExp_Explorer(self.faces[i], TopAbs_EDGE)
        while exp.More():
            e = TopoDS.Edge_s(exp.Current())
            if not BRep_Tool.Degenerated_s(e):
                c = BRepAdaptor_Curve(e)
                a, b = c.FirstParameter(), c.LastParameter()
                for k in range(n + 1):
                    pts.append(V(c.Value(a + (b - a) * k / n)))
            exp.Next()
        return np.array(pts) if pts else np.zeros((0, 3))

    # --- main axis ------------------------------------------------------------------------
    def find_axis(self):
        groups = defaultdict(float)
        reps = {}
        for d in self.face_info():
            if d["type"] != "cyl":
                continue
            e = unit(d["axis_d"])
            k = int(np.argmax(np.abs(e)))
            if e[k] < 0:
                e = -e
            p0 = d["axis_p"] - np.dot(d["axis_p"], e) * e
            key = tuple(np.round(e, 3)) + tuple(np.round(p0, 1))
            groups[key] += d["area"]
            reps[key] = (p0, e)
        if not groups:
            e = np.array([0, 0, 1.0])
            self.axis = (self.cog - np.dot(self.cog, e) * e, e)
        else:
            key = max(groups, key=groups.get)
            self.axis = reps[key]
        return self.axis

    def set_axis(self, axis):
        self.axis = axis

    def rz(self, pts):
        """cylindrical coordinates (r, z, theta) of points about the main axis"""
        O, e = self.axis
        x, y = perp_basis(e)
        q = np.atleast_2d(pts) - O
        z = q @ e
        rv = q - np.outer(z, e)
        r = np.linalg.norm(rv, axis=1)
        th = np.arctan2(rv @ y, rv @ x)
        return r, z, th

    def coaxial(self, d, tol_ang=1e-3, tol_off=0.02):
        O, e = self.axis
        if "axis_d" not in d:
            return False
        if abs(abs(np.dot(unit(d["axis_d"]), e)) - 1) > tol_ang:
            return False
        q = d["axis_p"] - O
        off = q - np.dot(q, e) * e
        return np.linalg.norm(off) < tol_off

    def axial_features(self):
        """coaxial cylinders / perpendicular planes / coaxial cones in (r, z) terms"""
        O, e = self.axis
        cyl, pla, con, tor = [], [], [], []
        for d in self.face_info():
            bp = d["bpts"]
            if len(bp) == 0:
                continue
            r, z, th = self.rz(bp)
            if d["type"] == "cyl" and self.coaxial(d):
                cyl.append({"i": d["i"], "r": d["r"], "z0": z.min(), "z1": z.max(), "concave": d["concave"],
                            "full": d["uspan"] > 2 * math.pi - 1e-3, "uspan": d["uspan"]})
            elif d["type"] == "plane" and d["normal"] is not None and abs(abs(np.dot(d["normal"], e)) - 1) < 1e-4:
                pla.append({"i": d["i"], "z": float(np.mean(z)), "rmin": r.min(), "rmax": r.max(),
                            "nz": float(np.sign(np.dot(d["normal"], e)))})
            elif d["type"] == "cone" and self.coaxial(d):
                con.append({"i": d["i"], "z0": z.min(), "z1": z.max(), "rmin": r.min(), "rmax": r.max(),
                            "semi": d["semi"]})
            elif d["type"] == "torus" and self.coaxial(d):
                tor.append({"i": d["i"], "z0": z.min(), "z1": z.max(), "rmin": r.min(), "rmax": r.max(),
                            "rf": d["r"]})
        return cyl, pla, con, tor

    def describe_face(self, i):
        d = self.face_info()[i]
        if self.axis is None:
            self.find_axis()
        bp = d["bpts"]
        r, z, th = self.rz(bp) if len(bp) else (np.zeros(1), np.zeros(1), np.zeros(1))
        if d["type"] == "cyl":
            if self.coaxial(d):
                kind = "bore" if d["concave"] else "outer/journal"
                return "%s Ø%.2f (z %.1f…%.1f)" % (kind, 2 * d["r"], z.min(), z.max())
            hkind = "hole" if d["concave"] else "pin/boss"
            if abs(np.dot(unit(d["axis_d"]), self.axis[1])) > 0.999:
                c = d["axis_p"]
                rc, zc, thc = self.rz(np.array([c]))
                return "axial %s Ø%.2f (axis at r %.1f, θ %.0f°)" % (hkind, 2 * d["r"], rc[0], math.degrees(thc[0]))
            rc, zc, thc = self.rz(np.array([d["p_mid"]]))
            return "transverse %s Ø%.2f (near r %.1f, z %.1f, θ %.0f°)" % (hkind, 2 * d["r"], rc[0], zc[0], math.degrees(thc[0]))
        if d["type"] == "plane":
            n = d["normal"]
            if n is not None and abs(abs(np.dot(n, self.axis[1])) - 1) < 1e-4:
                return "face z=%.2f (r %.1f…%.1f)" % (np.mean(z), r.min(), r.max())
            return "plane (r %.1f…%.1f, z %.1f…%.1f)" % (r.min(), r.max(), z.min(), z.max())
        return "%s (r %.1f…%.1f, z %.1f…%.1f)" % (d["type"], r.min(), r.max(), z.min(), z.max())

    # --- surface sampling -----------------------------------------------------------------
    def sample_faces(self, h=1.5, cap=500, min_area=0.5, seed=1):
        """random points on every face (exact surface points via UV), with outward normals"""
        rng = np.random.default_rng(seed)
        BRepMesh_IncrementalMesh(self.solid, 0.05, False, 0.3, True)
        out = []  # (face index, point, normal)
        for i, f in enumerate(self.faces):
            loc = TopLoc_Location()
            tri = BRep_Tool.Triangulation_s(f, loc)
            if tri is None or not tri.HasUVNodes():
                continue
            nn = tri.NbNodes()
            xyz = np.array([V(tri.Node(k)) for k in range(1, nn + 1)])
            if not loc.IsIdentity():
                T = loc.Transformation()
                xyz = np.array([V(tri.Node(k).Transformed(T)) for k in range(1, nn + 1)])
            uv = np.array([[tri.UVNode(k).X(), tri.UVNode(k).Y()] for k in range(1, nn + 1)])
            tris = np.array([tri.Triangle(k).Get() for k in range(1, tri.NbTriangles() + 1)]) - 1
            if len(tris) == 0:
                continue
            a = xyz[tris[:, 1]] - xyz[tris[:, 0]]
            b = xyz[tris[:, 2]] - xyz[tris[:, 0]]
            ar = 0.5 * np.linalg.norm(np.cross(a, b), axis=1)
            A = ar.sum()
            if A < min_area:
                continue
            hh = max(h, math.sqrt(A / cap))
            n = int(min(cap, max(3, A / hh ** 2)))
            which = rng.choice(len(tris), size=n, p=ar / A)
            w = rng.random((n, 2))
            flip = w.sum(1) > 1
            w[flip] = 1 - w[flip]
            t = tris[which]
            uvp = uv[t[:, 0]] * (1 - w[:, :1] - w[:, 1:]) + uv[t[:, 1]] * w[:, :1] + uv[t[:, 2]] * w[:, 1:]
            for (u, v) in uvp:
                nrm = self.normal(i, u, v)
                if nrm is None:
                    continue
                out.append((i, self.point(i, u, v), nrm))
        return out


def common_volume(a, b):
    op = BRepAlgoAPI_Common(a, b)
    if not op.IsDone():
        return None
    g = GProp_GProps()
    BRepGProp.VolumeProperties_s(op.Shape(), g)
    return abs(g.Mass())


# ----------------------------------------------------------------------------------------------
# neighbour classification (review assembly) from dimensions only
# ----------------------------------------------------------------------------------------------
def annulus_dims(body):
    """if the body is a plain coaxial ring (2 full coaxial cylinders + planes/chamfers):
    (r_in, r_out, width) else None"""
    info = body.face_info()
    cyls = [d for d in info if d["type"] == "cyl"]
    if not cyls:
        return None
    body.find_axis()
    co = [d for d in cyls if body.coaxial(d)]
    if len(co) != len(cyls):
        return None
    r, z, th = body.rz(np.vstack([d["bpts"] for d in info if len(d["bpts"])]))
    rin = min(d["r"] for d in co if d["concave"]) if any(d["concave"] for d in co) else 0.0
    rout = max(d["r"] for d in co if not d["concave"]) if any(not d["concave"] for d in co) else None
    if rout is None:
        return None
    return rin, rout, z.max() - z.min(), z.min(), z.max()


def classify_neighbour(body, cat):
    info = body.face_info()
    types = [d["type"] for d in info]
    body.find_axis()
    if "torus" in types and all(t in ("torus", "plane", "cyl") for t in types):
        tor = [d for d in info if d["type"] == "torus"]
        if len(tor) <= 2:
            d2 = 2 * tor[0]["r"]
            return {"kind": "O-ring", "d2": d2, "d1": 2 * (tor[0]["R"] - tor[0]["r"]), "label": "O-ring d2 %.2f" % d2}
    an = annulus_dims(body)
    if an and an[0] > 0:
        rin, rout, w, z0, z1 = an
        b = cat.bearing_by_dDB(2 * rin, 2 * rout, w)
        if b:
            return {"kind": "bearing", "bearing": b, "d": 2 * rin, "D": 2 * rout, "B": w, "z0": z0, "z1": z1,
                    "label": "bearing %s (%g×%g×%g)" % (b["model"], b["d_mm"], b["D_mm"], b["B_mm"])}
        s = cat.seal_by(2 * rin, 2 * rout, w)
        if s:
            return {"kind": "lip seal", "d1": 2 * rin, "d2": 2 * rout, "b": w, "z0": z0, "z1": z1,
                    "label": "lip seal %g×%g×%g" % (2 * rin, 2 * rout, w)}
        for rg in cat.rings:
            if abs(rg["s"] - w) < 0.06 and (abs(2 * rin - rg["d2"]) < 0.3 or abs(2 * rout - rg["d2"]) < 0.3
                                            or abs(2 * rout - rg["d1"]) < 0.6 or abs(2 * rin - rg["d1"]) < 0.6):
                return {"kind": "retaining ring", "ring": rg, "z0": z0, "z1": z1,
                        "label": "retaining ring (s %.2f, Ø%.1f/%.1f)" % (w, 2 * rin, 2 * rout)}
        span = rout - rin
        for o in cat.orings:
            # O-rings may be modelled as the rectangle they fill when squeezed: radial span = gland depth
            if abs(span - o["rd"]) < 0.05 and w <= o["rw"] + 0.05:
                return {"kind": "O-ring", "d2": o["d2"], "model": "rectangle (radial gland)", "rin": rin, "rout": rout, "w": w,
                        "z0": z0, "z1": z1, "label": "O-ring d2 %.2f Ø%.1f (radial)" % (o["d2"], 2 * rin)}
            if abs(w - o["fd"]) < 0.05 and span <= o["fw"] + 0.05:
                return {"kind": "O-ring", "d2": o["d2"], "model": "rectangle (face gland)", "rin": rin, "rout": rout, "w": w,
                        "z0": z0, "z1": z1, "label": "O-ring d2 %.2f Ø%.1f (face)" % (o["d2"], 2 * rin)}
        return {"kind": "ring/sleeve", "rin": rin, "rout": rout, "w": w, "z0": z0, "z1": z1,
                "label": "ring body Ø%.1f/Ø%.1f×%.1f" % (2 * rin, 2 * rout, w)}
    # screws: two coaxial convex cylinders, the larger ≈ ISO 4762 dk, the smaller ≈ thread d or tap drill
    cyl, pla, con, tor = body.axial_features()
    conv = sorted({round(c["r"] * 2, 2) for c in cyl if not c["concave"]})
    if 2 <= len(conv) <= 4 and body.vol < 2e5:
        for th, h in cat.heads.items():
            if any(abs(x - h["dk"]) < 0.15 for x in conv):
                t = [x for x in cat.threads if x["thread"] == th][0]
                if any(abs(x - t["d"]) < 0.05 or abs(x - t["tap"]) < 0.05 or abs(x - t["d3"]) < 0.05 for x in conv):
                    shank = [c for c in cyl if not c["concave"] and min(abs(2 * c["r"] - t["d"]), abs(2 * c["r"] - t["tap"]),
                                                                         abs(2 * c["r"] - t["d3"])) < 0.05]
                    return {"kind": "screw", "thread": th, "d": t["d"], "P": t["P"], "shank_d": 2 * shank[0]["r"],
                            "label": "socket screw %s" % th}
        for p in cat.ports:
            if any(abs(x - p["tap"]) < 0.05 or abs(x - p["d"]) < 0.05 for x in conv) and any(
                    abs(x - p["collar"]) < 0.6 for x in conv):
                return {"kind": "plug", "thread": p["thread"], "label": "plug %s" % p["thread"]}
    return {"kind": "body", "label": "body (%.0f mm³)" % body.vol}


# ----------------------------------------------------------------------------------------------
# holes
# ----------------------------------------------------------------------------------------------
def find_holes(body, cat):
    O, e = body.axis
    info = body.face_info()
    groups = defaultdict(list)
    keys = {}
    for d in info:
        if d["type"] in ("cyl", "cone") and not body.coaxial(d):
            a = unit(d["axis_d"])
            k = int(np.argmax(np.abs(a)))
            if a[k] < 0:
                a = -a
            p0 = d["axis_p"] - np.dot(d["axis_p"], a) * a
            key = tuple(np.round(a, 3)) + tuple(np.round(p0, 2))
            groups[key].append(d)
            keys[key] = (p0, a)
    holes = []
    for key, ds in groups.items():
        if not any(d["type"] == "cyl" and d["concave"] for d in ds):
            continue
        p0, a = keys[key]
        segs = []
        for d in ds:
            if d["type"] != "cyl" or not d["concave"] or len(d["bpts"]) == 0:
                continue
            t = (d["bpts"] - p0) @ a
            segs.append({"r": d["r"], "t0": t.min(), "t1": t.max(), "uspan": d["uspan"], "i": [d["i"]]})
        # merge split faces of one cylinder
        segs.sort(key=lambda s: (round(s["r"], 3), s["t0"]))
        merged = []
        for s in segs:
            if merged and abs(merged[-1]["r"] - s["r"]) < 1e-3 and s["t0"] <= merged[-1]["t1"] + 1e-3 and \
                    abs(s["t0"] - merged[-1]["t0"]) < 1e-3 and abs(s["t1"] - merged[-1]["t1"]) < 1e-3:
                merged[-1]["uspan"] += s["uspan"]
                merged[-1]["i"] += s["i"]
            else:
                merged.append(dict(s))
        merged.sort(key=lambda s: s["t0"])
        allcones = []
        for d in ds:
            if d["type"] == "cone" and len(d["bpts"]):
                t = (d["bpts"] - p0) @ a
                rr = np.linalg.norm((d["bpts"] - p0) - np.outer(t, a), axis=1)
                allcones.append({"semi": d["semi"], "t0": t.min(), "t1": t.max(), "rmax": rr.max(), "rmin": rr.min(),
                                 "i": d["i"]})
        # holes on one axis line but apart (e.g. two opposite radial ports) are separate holes
        runs = []
        for s in merged:
            if runs and s["t0"] <= runs[-1][-1]["t1"] + 0.01:
                runs[-1].append(s)
            else:
                runs.append([s])
        for run in runs:
            lo_t, hi_t = run[0]["t0"], max(s["t1"] for s in run)
            cones = [c for c in allcones if c["t1"] >= lo_t - 3.0 and c["t0"] <= hi_t + 3.0
                     and not any(c["t1"] >= r2[0]["t0"] - 0.01 and c["t0"] <= max(s["t1"] for s in r2) + 0.01 for r2 in runs if r2 is not run)]
            holes.append(_hole_record(body, p0, a, run, cones, info))
    for h in holes:
        classify_hole(h, cat)
    return holes


def _hole_record(body, p0, a, merged, cones, info):
    O, e = body.axis
    if True:
        h = {"p0": p0, "a": a, "segs": merged, "cones": cones,
             "faces": sorted({i for s in merged for i in s["i"]} | {c["i"] for c in cones})}
        # position relative to the main axis
        ang = math.degrees(math.acos(min(1.0, abs(float(np.dot(a, e))))))
        h["angle_to_axis"] = ang
        mid_t = 0.5 * (merged[0]["t0"] + merged[-1]["t1"])
        c = p0 + mid_t * a
        r, z, th = body.rz(np.array([c]))
        h["center"] = c
        # distance of the hole axis from the main axis
        w = np.cross(a, e)
        if np.linalg.norm(w) < 1e-6:
            dist = float(np.linalg.norm((p0 - O) - np.dot(p0 - O, e) * e))
        else:
            dist = abs(float(np.dot(p0 - O, unit(w))))
        h["kind_dir"] = "axial" if ang < 1 else ("radial" if ang > 89 and dist < 0.5 else "oblique")
        h["r_axis"] = float(r[0]) if h["kind_dir"] == "axial" else dist
        h["theta"] = math.degrees(th[0])
        h["z"] = float(z[0])
        # ends: cast along ±a from the middle of the smallest segment
        smallest = min(merged, key=lambda s: s["r"])
        h["dmin"] = 2 * smallest["r"]
        cm = p0 + 0.5 * (smallest["t0"] + smallest["t1"]) * a
        ends = {}
        for sgn in (+1, -1):
            hits = body.cast(cm, sgn * a, tmin=1e-4)
            tm = 0.5 * (smallest["t0"] + smallest["t1"])
            seg_end = (max(s["t1"] for s in merged) - tm) if sgn > 0 else (tm - min(s["t0"] for s in merged))
            cone_end = 0.0
            for cn in cones:
                ce = (cn["t1"] - tm) if sgn > 0 else (tm - cn["t0"])
                cone_end = max(cone_end, ce)
            first_in = None
            for k, (t, i, u, v) in enumerate(hits):
                n = body.normal(i, u, v)
                if n is not None and np.dot(n, sgn * a) < 0:
                    first_in = k
                    break
            if first_in is None:
                ends[sgn] = {"kind": "open", "into": "outside"}
                continue
            t_in, i_in, _, _ = hits[first_in]
            t_out = next((t for (t, i, u, v) in hits[first_in + 1:]
                          if (lambda n: n is not None and np.dot(n, sgn * a) > 0)(body.normal(i, u, v))), None)
            if t_in <= max(seg_end, cone_end) + 0.05 and (i_in in h["faces"] or info[i_in]["type"] in ("plane", "cone")):
                fl = (t_out - t_in) if t_out is not None else None
                ends[sgn] = {"kind": "blind", "floor": fl, "depth_from_mid": t_in,
                             "bottom": "cone %.0f°" % (2 * info[i_in]["semi"]) if info[i_in]["type"] == "cone" else info[i_in]["type"]}
            else:
                ends[sgn] = {"kind": "open", "into": "internal space of the part (crosses %.1f mm of air, then %s)"
                             % (t_in - seg_end, body.describe_face(i_in))}
        h["ends"] = ends
        return h


def classify_hole(h, cat):
    segs = h["segs"]
    smallest = min(segs, key=lambda s: s["r"])
    d = 2 * smallest["r"]
    h["drill_len"] = smallest["t1"] - smallest["t0"]
    h["wall_broken"] = smallest["uspan"] < 2 * math.pi - 1e-3
    tap = cat.thread_by_tap(d)
    clr = cat.clearance_by_dia(d)
    maj = cat.thread_by_major(d)
    nopen = sum(1 for v in h["ends"].values() if v["kind"] == "open")
    blind = any(v["kind"] == "blind" for v in h["ends"].values())
    bigger = [s for s in segs if s["r"] > smallest["r"] + 0.05]
    h["counterbore"] = None
    if bigger:
        cb = max(bigger, key=lambda s: s["r"])
        h["counterbore"] = {"d": 2 * cb["r"], "depth": cb["t1"] - cb["t0"]}
    csk = [c for c in h["cones"] if abs(c["semi"] - 45) < 2 and c["rmin"] <= smallest["r"] + 0.05]
    h["countersink"] = (2 * max(c["rmax"] for c in csk)) if csk else None
    h["drill_point"] = [c for c in h["cones"] if abs(c["semi"] - 59) < 2]
    kind, thread = "unclassified", None
    port = [t for t in tap if t["std"].startswith("DIN 908")]
    iso = [t for t in tap if t["std"] == "ISO 261"]
    if port and (h["kind_dir"] == "radial" or (h["counterbore"] and h["counterbore"]["depth"] < 3.5)):
        kind, thread = "port", port[0]
    elif iso and (blind or not (clr and h["counterbore"])):
        kind, thread = "tapped", iso[0]
    elif clr:
        th = clr[0][0]
        kind = "clearance"
        thread = dict([t for t in cat.threads if t["thread"] == th][0], fit=clr[0][1])
        if port and h["kind_dir"] != "axial":
            kind, thread = "port", port[0]
    elif port:
        kind, thread = "port", port[0]
    elif maj:
        kind, thread = "tapped (modelled at major Ø)", maj[0]
    h["kind"] = kind
    h["thread"] = thread
    h["alternatives"] = ([t["thread"] + " tap" for t in tap] + ["%s %s clearance" % c for c in clr])
    h["d"] = d


def hole_label(h):
    th = h["thread"]["thread"] if h.get("thread") else "?"
    return "%s %s Ø%.2f %s hole (r %.1f, θ %.0f°, z %.1f)" % (h["kind"], th, h["d"], h["kind_dir"], h["r_axis"],
                                                               h["theta"], h["z"])


def opening_positions(body, h):
    """(r, z) about the main axis of the points where the hole's outermost segments end"""
    out = {}
    t0 = min(s["t0"] for s in h["segs"])
    t1 = max(s["t1"] for s in h["segs"])
    for sgn, t in ((+1, t1), (-1, t0)):
        if h["ends"][sgn]["kind"] != "open":
            continue
        q = h["p0"] + t * h["a"]
        r, z, th = body.rz(np.array([q]))
        out[sgn] = (float(r[0]), float(z[0]))
    return out


# ----------------------------------------------------------------------------------------------
# edges: convex / concave, sharpness, breaks
# ----------------------------------------------------------------------------------------------
def edge_analysis(body):
    body.adj
    info = body.face_info()
    res = []
    for e, fl in body.edge_faces:
        if len(fl) != 2 or BRep_Tool.Degenerated_s(e):
            continue
        c = BRepAdaptor_Curve(e)
        try:
            L = GCPnts_AbscissaPoint.Length_s(c)
        except Exception:
            L = 0.0
        if L < 1e-3:
            continue
        tm = 0.5 * (c.FirstParameter() + c.LastParameter())
        p = V(c.Value(tm))
        ns = []
        for fi in fl:
            try:
                c2 = BRepAdaptor_Curve2d(e, body.faces[fi])
                uv = c2.Value(0.5 * (c2.FirstParameter() + c2.LastParameter()))
                ns.append(body.normal(fi, uv.X(), uv.Y()))
            except Exception:
                ns.append(None)
        if ns[0] is None or ns[1] is None:
            continue
        ang = math.degrees(math.acos(max(-1.0, min(1.0, float(np.dot(ns[0], ns[1]))))))
        if ang < 3:
            res.append({"faces": fl, "L": L, "angle": ang, "convex": None, "p": p})
            continue
        dvec = unit(ns[0] - ns[1])
        q = p + 0.02 * dvec
        convex = not body.inside(q)
        res.append({"faces": fl, "L": L, "angle": ang, "convex": convex, "p": p})
    # break faces (chamfers / fillets): narrow faces whose boundary edges are convex breaks or tangent
    per_face = defaultdict(list)
    for r_ in res:
        for fi in r_["faces"]:
            per_face[fi].append(r_)
    breaks = []
    for fi, es in per_face.items():
        perim = sum(x["L"] for x in es)
        width = 2 * info[fi]["area"] / perim if perim > 0 else 99
        if width > 2.6 or info[fi]["type"] not in ("cone", "plane", "torus", "cyl"):
            continue
        if all((x["convex"] is None) or (x["convex"] and x["angle"] < 75) for x in es):
            if info[fi]["type"] == "cyl" and any(x["convex"] is not None for x in es):
                continue
            breaks.append({"face": fi, "width": width, "L": perim / 2, "type": info[fi]["type"]})
    return res, breaks


# ----------------------------------------------------------------------------------------------
# bearing seats, journals, shoulders, grooves (coaxial features)
# ----------------------------------------------------------------------------------------------
def near(a, b, tol):
    return abs(a - b) <= tol


def seat_end(body, cat, seat, z_end, s, bore, cyl, pla, con, tor):
    """what stops a ring at one end of a bore (bore=True) or a journal (bore=False).
    s = +1 for the z1 end, -1 for the z0 end."""
    R = seat["r"]
    out = {"z": z_end}
    # fillet / cone right at the corner
    fil = [t for t in tor if (near(t["z0"], z_end, t["rf"] + 0.05) or near(t["z1"], z_end, t["rf"] + 0.05))
           and ((bore and near(t["rmax"], R, 0.05)) or (not bore and near(t["rmin"], R, 0.05)))]
    cone = [c for c in con if (near(c["z0"], z_end, 0.02) or near(c["z1"], z_end, 0.02))
            and ((bore and near(c["rmin"], R, 0.02) and c["rmax"] > R) or (not bore and near(c["rmax"], R, 0.02) and c["rmin"] < R))]
    cone_in = [c for c in con if (near(c["z0"], z_end, 0.02) or near(c["z1"], z_end, 0.02))
               and ((bore and near(c["rmax"], R, 0.02) and c["rmin"] < R) or (not bore and near(c["rmin"], R, 0.02) and c["rmax"] > R))]
    zz = z_end + s * (fil[0]["rf"] if fil else 0.0)
    rr_edge = (R - fil[0]["rf"]) if (fil and bore) else ((R + fil[0]["rf"]) if fil else R)
    if cone_in:
        c = cone_in[0]
        zz = c["z1"] if s > 0 else c["z0"]
        rr_edge = c["rmin"] if bore else c["rmax"]
    # shoulder: perpendicular plane facing the seat, reaching the seat radius
    if bore:
        sh = [p for p in pla if near(p["z"], zz, 0.05) and p["nz"] == -s and p["rmax"] <= R + 0.05
              and p["rmax"] >= rr_edge - 0.05 and p["rmin"] < R - 0.2]
    else:
        sh = [p for p in pla if near(p["z"], zz, 0.05) and p["nz"] == -s and p["rmin"] >= R - 0.05
              and p["rmin"] <= rr_edge + 0.05 and p["rmax"] > R + 0.2]
    if sh:
        if bore:
            out["kind"] = "shoulder"
            out["shoulder_d"] = 2 * min(p["rmin"] for p in sh)
        else:
            out["kind"] = "shoulder"
            out["shoulder_d"] = 2 * max(p["rmax"] for p in sh)
        out["fillet"] = fil[0]["rf"] if fil else (None if not cone_in else "cone %.0f°" % cone_in[0]["semi"])
        return out
    # ring groove: a short cylinder of larger (bore) / smaller (journal) radius right after the end
    gs = [g for g in cyl if g["concave"] == bore and ((bore and 0.05 < g["r"] - R < 6) or (not bore and 0.05 < R - g["r"] < 6))
          and ((s > 0 and near(g["z0"], z_end, 0.05)) or (s < 0 and near(g["z1"], z_end, 0.05)))
          and (g["z1"] - g["z0"]) < 8]
    if gs:
        g = gs[0]
        far = g["z1"] if s > 0 else g["z0"]
        cont = [c for c in cyl if near(c["r"], R, 0.02) and c["concave"] == bore and
                ((s > 0 and near(c["z0"], far, 0.05)) or (s < 0 and near(c["z1"], far, 0.05)))]
        out["groove_d"] = 2 * g["r"]
        out["groove_w"] = g["z1"] - g["z0"]
        if cont:
            out["kind"] = "ring groove"
            out["land"] = (cont[0]["z1"] - cont[0]["z0"])
        else:
            # the bore/journal may end right after the groove: land up to the end face (chamfer included)
            endp = [p for p in pla if p["nz"] == s and ((s > 0 and p["z"] > far - 1e-6) or (s < 0 and p["z"] < far + 1e-6))
                    and ((bore and p["rmin"] <= R + 1.5) or (not bore and p["rmax"] >= R - 1.5))]
            if endp:
                zf = min(endp, key=lambda p: abs(p["z"] - far))["z"]
                out["kind"] = "ring groove"
                out["land"] = abs(zf - far)
            else:
                out["kind"] = "groove/undercut at corner"
        return out
    # open end: step to a larger bore / end face, or a lead-in chamfer
    if cone:
        out["kind"] = "open"
        out["leadin"] = cone[0]["semi"]
        out["leadin_len"] = cone[0]["z1"] - cone[0]["z0"]
        return out
    if fil:
        out["kind"] = "open"
        out["leadin"] = "radius %.2f" % fil[0]["rf"]
        return out
    st = [p for p in pla if near(p["z"], z_end, 0.05) and p["nz"] == s and
          ((bore and near(p["rmin"], R, 0.05)) or (not bore and near(p["rmax"], R, 0.05)))]
    out["kind"] = "open"
    out["leadin"] = None if st else "unknown"
    return out


def seats_and_grooves(body, cat):
    """candidate bearing seats/journals (ISO 15 diameters), ring and O-ring grooves, seal bores"""
    cyl, pla, con, tor = body.axial_features()
    res = {"seats": [], "grooves": []}
    for c in cyl:
        dia = 2 * c["r"]
        cands = cat.bearing_by_D(dia) if c["concave"] else cat.bearing_by_d(dia)
        if not cands:
            continue
        b = cands[0]
        L = c["z1"] - c["z0"]
        ends = [seat_end(body, cat, c, c["z0"], -1, c["concave"], cyl, pla, con, tor),
                seat_end(body, cat, c, c["z1"], +1, c["concave"], cyl, pla, con, tor)]
        res["seats"].append({"cyl": c, "bearing": b, "bore": c["concave"], "L": L, "ends": ends, "dia": dia})
    # grooves
    for g in cyl:
        w = g["z1"] - g["z0"]
        if w > 9 or w < 0.3:
            continue
        # radial groove: walls are perpendicular planes at both ends
        if g["concave"]:
            w0 = [p for p in pla if near(p["z"], g["z0"], 0.03) and p["nz"] == +1 and near(p["rmax"], g["r"], 0.05) and p["rmin"] < g["r"] - 0.3]
            w1 = [p for p in pla if near(p["z"], g["z1"], 0.03) and p["nz"] == -1 and near(p["rmax"], g["r"], 0.05) and p["rmin"] < g["r"] - 0.3]
            if w0 and w1:
                r_land = max(max(p["rmin"] for p in w0), max(p["rmin"] for p in w1))
                depth = g["r"] - r_land
                res["grooves"].append({"type": "radial (in bore)", "bottom_d": 2 * g["r"], "land_d": 2 * r_land,
                                       "depth": depth, "width": w, "z0": g["z0"], "z1": g["z1"], "face": g["i"],
                                       "walls": [p["i"] for p in w0 + w1]})
        else:
            w0 = [p for p in pla if near(p["z"], g["z0"], 0.03) and p["nz"] == +1 and near(p["rmin"], g["r"], 0.05) and p["rmax"] > g["r"] + 0.3]
            w1 = [p for p in pla if near(p["z"], g["z1"], 0.03) and p["nz"] == -1 and near(p["rmin"], g["r"], 0.05) and p["rmax"] > g["r"] + 0.3]
            if w0 and w1:
                r_land = min(min(p["rmax"] for p in w0), min(p["rmax"] for p in w1))
                depth = r_land - g["r"]
                res["grooves"].append({"type": "radial (on shaft/spigot)", "bottom_d": 2 * g["r"], "land_d": 2 * r_land,
                                       "depth": depth, "width": w, "z0": g["z0"], "z1": g["z1"], "face": g["i"],
                                       "walls": [p["i"] for p in w0 + w1]})
    # face grooves: an annular bottom plane between a convex inner wall and a concave outer wall of equal height
    for p in pla:
        if p["rmax"] - p["rmin"] > 12:
            continue
        inner = [c for c in cyl if not c["concave"] and near(c["r"], p["rmin"], 0.03) and (near(c["z0"], p["z"], 0.03) or near(c["z1"], p["z"], 0.03))]
        outer = [c for c in cyl if c["concave"] and near(c["r"], p["rmax"], 0.03) and (near(c["z0"], p["z"], 0.03) or near(c["z1"], p["z"], 0.03))]
        if inner and outer:
            hi = inner[0]["z1"] - inner[0]["z0"]
            ho = outer[0]["z1"] - outer[0]["z0"]
            depth = min(hi, ho)
            top = p["z"] + p["nz"] * depth
            res["grooves"].append({"type": "face", "r_in": p["rmin"], "r_out": p["rmax"], "depth": depth,
                                   "width": p["rmax"] - p["rmin"], "z_bottom": p["z"], "z_top": top, "nz": p["nz"],
                                   "face": p["i"]})
    return res


def classify_groove(g, cat):
    """match against DIN 471/472 and ISO 3601-2 (catalog) and the HOUSING_RULES ranges"""
    out = []
    if g["type"].startswith("radial"):
        bore = g["type"] == "radial (in bore)"
        kind = "bore" if bore else "shaft"
        ring = cat.ring(kind, g["land_d"], tol=0.06)
        if ring and near(ring["d2"], g["bottom_d"], 0.12) and near(ring["m"], g["width"], 0.12):
            out.append(("DIN 472" if bore else "DIN 471", ring, abs(ring["d2"] - g["bottom_d"]) + abs(ring["m"] - g["width"])))
        for o in cat.orings:
            if near(o["rd"], g["depth"], 0.15) and near(o["rw"], g["width"], 0.3):
                out.append(("ISO 3601 radial gland d2 %.2f" % o["d2"], o, abs(o["rd"] - g["depth"]) + abs(o["rw"] - g["width"])))
    else:
        for o in cat.orings:
            if near(o["fd"], g["depth"], 0.15) and near(o["fw"], g["width"], 0.3):
                out.append(("ISO 3601 face gland d2 %.2f" % o["d2"], o, abs(o["fd"] - g["depth"]) + abs(o["fw"] - g["width"])))
    out.sort(key=lambda x: x[2])
    return out


# ----------------------------------------------------------------------------------------------
# planar sections through the axis (render + raster)
# ----------------------------------------------------------------------------------------------
def section_polys(solid, O, xdir, e, L):
    """triangles (list of (3,2) arrays in (u, w) = (along xdir, along axis)) and outline polylines
    of the section of `solid` by the plane through O spanned by xdir and e."""
    nrm = unit(np.cross(e, xdir))
    pln = gp_Pln(gp_Ax3(P(O), gp_Dir(*map(float, nrm)), gp_Dir(*map(float, xdir))))
    face = BRepBuilderAPI_MakeFace(pln, -L, L, -L, L).Face()
    op = BRepAlgoAPI_Common(solid, face)
    if not op.IsDone():
        return [], []
    shp = op.Shape()
    BRepMesh_IncrementalMesh(shp, 0.01, False, 0.2, True)
    tris, lines = [], []
    exp = TopExp_Explorer(shp, TopAbs_FACE)
    while exp.More():
        f = TopoDS.Face_s(exp.Current())
        loc = TopLoc_Location()
        tri = BRep_Tool.Triangulation_s(f, loc)
        if tri is not None:
            T = loc.Transformation()
            xyz = np.array([V(tri.Node(k).Transformed(T)) for k in range(1, tri.NbNodes() + 1)])
            uw = np.c_[(xyz - O) @ xdir, (xyz - O) @ e]
            for k in range(1, tri.NbTriangles() + 1):
                a, b, c = tri.Triangle(k).Get()
                tris.append(uw[[a - 1, b - 1, c - 1]])
        ee = TopExp_Explorer(f, TopAbs_EDGE)
        while ee.More():
            ed = TopoDS.Edge_s(ee.Current())
            if not BRep_Tool.Degenerated_s(ed):
                c = BRepAdaptor_Curve(ed)
                a0, a1 = c.FirstParameter(), c.LastParameter()
                n = 2 if c.GetType() == 0 else 40
                pts = np.array([V(c.Value(a0 + (a1 - a0) * k / n)) for k in range(n + 1)])
                lines.append(np.c_[(pts - O) @ xdir, (pts - O) @ e])
            ee.Next()
        exp.Next()
    return tris, lines


def render_part_section(path_png, title, tris, lines, extra=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    fig, ax = plt.subplots(figsize=(8, 8))
    if tris:
        # w (axis) horizontal, u (radial) vertical
        pc = PolyCollection([t[:, ::-1] for t in tris], facecolor="#9fb6cd", edgecolor="#9fb6cd", linewidth=0.2)
        ax.add_collection(pc)
    for ln in lines:
        ax.plot(ln[:, 1], ln[:, 0], "k-", lw=0.6)
    if extra:
        extra(ax)
    ax.axhline(0, color="r", lw=0.5, ls="-.")
    ax.set_aspect("equal")
    ax.autoscale()
    ax.set_xlabel("axial position z [mm]")
    ax.set_ylabel("radial position in the section plane [mm]")
    ax.set_title(title, fontsize=9)
    ax.grid(True, lw=0.2)
    fig.tight_layout()
    fig.savefig(path_png, dpi=130)
    plt.close(fig)


def rasterize(polys_by_label, umin, wmin, px, shape):
    from PIL import Image, ImageDraw
    img = Image.new("I", (shape[1], shape[0]), 0)
    dr = ImageDraw.Draw(img)
    for lab, tris in polys_by_label:
        for t in tris:
            pts = [((w - wmin) / px, (u - umin) / px) for (u, w) in t]
            dr.polygon(pts, fill=int(lab), outline=int(lab))
    return np.array(img, dtype=np.int32)


# ----------------------------------------------------------------------------------------------
# folder loading and matching
# ----------------------------------------------------------------------------------------------
def same_shape(b1, b2, rel=2e-4):
    if abs(b1.vol - b2.vol) > rel * max(abs(b1.vol), 1):
        return False
    if abs(b1.area - b2.area) > rel * max(b1.area, 1):
        return False
    return bool(np.all(np.abs(b1.pm - b2.pm) <= 1e-3 * np.maximum(np.abs(b1.pm), 1)))


def axis_line_match(O1, e1, O2, e2, tol=0.05):
    if abs(abs(np.dot(e1, e2)) - 1) > 1e-4:
        return False
    q = O2 - O1
    return np.linalg.norm(q - np.dot(q, e1) * e1) < tol


class Folder:
    def __init__(self, path, cat, log):
        self.path = path
        self.cat = cat
        self.log = log
        self.F = Findings()
        self.model = None
        self.results = {}
        rj = os.path.join(path, "results.json")
        if os.path.exists(rj):
            with open(rj, encoding="utf-8") as f:
                self.results = json.load(f)
        self.model = self.results.get("model") or os.path.basename(os.path.normpath(path))
        m = self.model.split("-")
        self.family = ("FD-2" if self.model.startswith("FD") and self.model.endswith("-2") else
                       "FD-0" if self.model.startswith("FD") and self.model.endswith("-0") else
                       "GH" if self.model.endswith("-GH") else
                       "2A-GR" if self.model.endswith("2A-GR") else "unknown")
        try:
            self.size = int(m[1])
        except Exception:
            self.size = None
        # allowed uses of results.json: model, material (density), lubricant
        self.material = (self.results.get("design_options") or {}).get("material") or "steel"
        self.lubrication = (self.results.get("duty") or {}).get("lubrication")
        self.A = cat.oil_A.get(self.size) if self.family.startswith("FD") else None

    def load(self):
        steps = sorted(glob.glob(os.path.join(self.path, "*.step")))
        self.part_files = [p for p in steps if os.path.basename(p) not in ("assembly.step", "review_assembly.step")]
        self.parts = []  # (name, Body from part file, n_solids, file)
        for p in self.part_files:
            nm = os.path.splitext(os.path.basename(p))[0]
            sol = [s for (_, s) in read_step_solids(p) if s is not None]
            b = Body(sol[0], nm) if sol else None
            self.parts.append({"name": nm, "file": p, "n_solids": len(sol), "body": b, "solids": sol})
        self.assembly = []
        ap = os.path.join(self.path, "assembly.step")
        if os.path.exists(ap):
            self.assembly = [Body(s, n) for n, s in read_step_solids(ap) if s is not None]
        self.review = []
        rp = os.path.join(self.path, "review_assembly.step")
        if os.path.exists(rp):
            self.review = [Body(s, n) for n, s in read_step_solids(rp) if s is not None]
        self.scene = self.review if self.review else self.assembly
        self.scene_name = "review_assembly.step" if self.review else "assembly.step"
        # match parts to scene bodies by volume, area and principal moments (not by name)
        used = set()
        for prt in self.parts:
            prt["scene"] = None
            if prt["body"] is None:
                continue
            cands = [k for k, sb in enumerate(self.scene) if k not in used and same_shape(prt["body"], sb)]
            if cands:
                # geometry decides; among congruent copies the one labelled like the file is preferred for display
                k = next((k for k in cands if self.scene[k].name.endswith(prt["name"])), cands[0])
                prt["scene"] = k
                used.add(k)
            prt["in_assembly"] = any(same_shape(prt["body"], ab) for ab in self.assembly)
        self.part_of_scene = {prt["scene"]: prt["name"] for prt in self.parts if prt["scene"] is not None}
        # classify the other scene bodies from their dimensions
        self.neigh = {}
        for k, sb in enumerate(self.scene):
            if k in self.part_of_scene:
                continue
            self.neigh[k] = classify_neighbour(sb, self.cat)
        # analysis body of each part: its placed copy in the scene if found
        for prt in self.parts:
            prt["ab"] = self.scene[prt["scene"]] if prt["scene"] is not None else prt["body"]
            if prt["ab"] is not None:
                prt["ab"].find_axis()
        self.main_axis = None
        big = max((p for p in self.parts if p["ab"] is not None), key=lambda p: p["ab"].vol, default=None)
        if big:
            self.main_axis = big["ab"].axis

    def label(self, k):
        if k in self.part_of_scene:
            return self.part_of_scene[k]
        n = self.neigh.get(k, {})
        return "%s [STEP label: %s]" % (n.get("label", "body"), self.scene[k].name)

    def short(self, k):
        if k in self.part_of_scene:
            return self.part_of_scene[k]
        n = self.neigh.get(k, {})
        if n.get("kind") in ("body", "ring/sleeve"):
            lab = re.sub(r"^\d+_", "", self.scene[k].name)[:40]
            return "%s ['%s']" % (n.get("label", "body %d" % k), lab)
        return n.get("label", "body %d" % k)


# ----------------------------------------------------------------------------------------------
# checks
# ----------------------------------------------------------------------------------------------
def check_validity(fd):
    F = fd.F
    for prt in fd.parts:
        nm = prt["name"]
        if prt["n_solids"] != 1:
            F.add("blocker", nm, "part file holds %d solids (expected exactly one)" % prt["n_solids"],
                  "%d solids" % prt["n_solids"], "one closed solid per part")
        for s in prt["solids"]:
            ok = BRepCheck_Analyzer(s).IsValid()
            shells = []
            exp = TopExp_Explorer(s, TopAbs_SHELL)
            while exp.More():
                shells.append(BRep_Tool.IsClosed_s(exp.Current()))
                exp.Next()
            b = Body(s, nm)
            b.adj
            free = sum(1 for e, fl in b.edge_faces if len(fl) == 1 and not BRep_Tool.IsClosed_s(e, b.faces[fl[0]])
                       and not BRep_Tool.Degenerated_s(e))
            vol = b.vol
            if not ok or not all(shells) or len(shells) != 1 or free or vol <= 0:
                F.add("blocker", nm, "solid not valid/closed: BRepCheck %s, %d shell(s), closed %s, %d free edge(s), volume %.1f mm³"
                      % ("ok" if ok else "FAILED", len(shells), all(shells), free, vol),
                      "see finding", "single valid closed solid")
            else:
                F.ok(nm, "valid closed solid", "BRepCheck ok, 1 closed shell, 0 free edges, V = %.0f mm³" % vol)
        if prt["body"] is not None and fd.assembly and not prt["in_assembly"]:
            F.add("major", nm, "part file not found in assembly.step (no solid of equal volume/area/inertia): assembly out of date?",
                  "V %.0f mm³" % prt["body"].vol, "assembly consistent with part files")
        if prt["body"] is not None and fd.review and prt["scene"] is None:
            F.add("minor", nm, "part not found in review_assembly.step; assembly checks for it were skipped", "-", "-")
    for k, sb in enumerate(fd.scene):
        if not BRepCheck_Analyzer(sb.solid).IsValid() or sb.vol <= 0:
            F.add("major", fd.short(k), "assembly body not a valid solid (%s)" % fd.scene_name, "V %.1f mm³" % sb.vol, "valid solids")


def check_interference(fd, tol=0.01):
    F = fd.F
    n = len(fd.scene)
    boxes = [sb.bb for sb in fd.scene]
    checked = 0
    bad = 0
    touching = 0
    for i in range(n):
        for j in range(i + 1, n):
            if boxes[i] is None or boxes[j] is None:
                continue
            bi = (boxes[i][0] - 0.01, boxes[i][1] + 0.01)
            if not boxes_overlap(bi, boxes[j]):
                continue
            v = common_volume(fd.scene[i].solid, fd.scene[j].solid)
            checked += 1
            if v is None:
                F.add("minor", fd.short(i), "boolean common with %s failed: interference not measured" % fd.short(j), "-", "-")
                continue
            if v > tol:
                bad += 1
                sev = "blocker" if v > 1.0 else "minor"
                F.add(sev, "%s ↔ %s" % (fd.short(i), fd.short(j)),
                      "bodies interfere in %s" % fd.scene_name, "common volume %.3f mm³" % v,
                      "no interference (tolerance %.2f mm³)" % tol)
            else:
                touching += 1
    F.ok("assembly", "interference", "%d body pairs with overlapping boxes checked by boolean common in %s; %d interfere"
         % (checked, fd.scene_name, bad))


def ring_bands(nb):
    d, D = nb["d"], nb["D"]
    wall = (D - d) / 2
    a, b = min(0.4, 0.05 * wall), min(0.9, 0.12 * wall)
    return ([D / 2 - a, D / 2 - b], [d / 2 + a, d / 2 + b])


def bodies_at(fd, p, exclude=(), margin=0.0):
    hits = []
    for k, sb in enumerate(fd.scene):
        if k in exclude or sb.bb is None:
            continue
        lo, hi = sb.bb
        if np.any(p < lo - margin) or np.any(p > hi + margin):
            continue
        if sb.inside(p):
            hits.append(k)
    return hits


def bearing_frame(fd, k):
    sb = fd.scene[k]
    sb.find_axis()
    nb = fd.neigh[k]
    O, e = sb.axis
    # z-range of the bearing along its own axis
    pts = np.vstack([d["bpts"] for d in sb.face_info() if len(d["bpts"])])
    z = (pts - O) @ e
    return O, e, z.min(), z.max()


def check_bearings(fd):
    """bearing rings: stops on both faces, which body stops which ring, journal/seat support"""
    F = fd.F
    brgs = [k for k, n in fd.neigh.items() if n["kind"] == "bearing"]
    if not brgs:
        if fd.family in ("FD-2", "2A-GR"):
            F.add("info", "assembly", "no bearing bodies found in %s (recognised by ISO 15 d×D×B): bearing stop checks skipped" % fd.scene_name, "-", "-")
        return {}
    # stacks of touching coaxial bearings
    frames = {k: bearing_frame(fd, k) for k in brgs}
    parent = {k: k for k in brgs}

    def find(k):
        while parent[k] != k:
            k = parent[k]
        return k
    for a in brgs:
        for b in brgs:
            if a < b:
                Oa, ea, a0, a1 = frames[a]
                Ob, eb, b0, b1 = frames[b]
                if axis_line_match(Oa, ea, Ob, eb):
                    off = np.dot(Ob - Oa, ea) * np.sign(np.dot(ea, eb))
                    if np.sign(np.dot(ea, eb)) < 0:
                        b0, b1 = -b1, -b0
                    b0 += off
                    b1 += off
                    if abs(a1 - b0) < 0.05 or abs(b1 - a0) < 0.05:
                        parent[find(a)] = find(b)
    stacks = defaultdict(list)
    for k in brgs:
        stacks[find(k)].append(k)
    seat_holders = {}
    x_ang = np.radians(np.arange(0, 360, 30) + 7.0)
    for root, ks in stacks.items():
        O, e, _, _ = frames[ks[0]]
        x, y = perp_basis(e)
        zs = []
        for k in ks:
            Ok, ek, z0, z1 = frames[k]
            off = np.dot(Ok - O, e)
            if np.dot(ek, e) < 0:
                z0, z1 = -z1, -z0
            zs.append((z0 + off, z1 + off, k))
        zs.sort()
        nb = fd.neigh[ks[0]]
        model = nb["bearing"]["model"]
        lo, hi = zs[0][0], zs[-1][1]
        zmid = float(np.dot(O + e * (lo + hi) / 2 - fd.main_axis[0], fd.main_axis[1])) if fd.main_axis else 0.0
        name = "%s×%d @z%+.0f" % (model, len(ks), zmid)
        outer_band, inner_band = ring_bands(nb)
        holders = {"outer": set(), "inner": set()}
        for ring, band in (("outer", outer_band), ("inner", inner_band)):
            for zend, s in ((lo, -1), (hi, +1)):
                cover = defaultdict(int)
                npts = 0
                for r_ in band:
                    for a in x_ang:
                        p = O + e * (zend + s * 0.03) + r_ * (math.cos(a) * x + math.sin(a) * y)
                        npts += 1
                        for kk in bodies_at(fd, p, exclude=ks):
                            cover[kk] += 1
                stop = {kk: c / npts for kk, c in cover.items() if c / npts >= 0.3}
                side = "−z" if s < 0 else "+z"
                if not stop:
                    # measure the gap to whatever is there
                    gaps = []
                    for a in x_ang[:4]:
                        p = O + e * zend + band[0] * (math.cos(a) * x + math.sin(a) * y)
                        best = None
                        for kk, sb in enumerate(fd.scene):
                            if kk in ks:
                                continue
                            h = sb.cast(p, s * e, tmin=1e-4, tmax=50)
                            if h and (best is None or h[0][0] < best[0]):
                                best = (h[0][0], kk)
                        gaps.append(best)
                    g = [x_ for x_ in gaps if x_ is not None]
                    if g:
                        gmin = min(g)
                        sev = "major" if gmin[0] > 0.5 else "info"
                        F.add(sev, name, "%s ring not in contact on its %s face: nearest %s at %.2f mm (axial play / float)"
                              % (ring, side, fd.short(gmin[1]), gmin[0]), "gap %.2f mm" % gmin[0],
                              "HOUSING_RULES §1 axial location: a stop on both sides (float only on the non-locating bearing)")
                    else:
                        F.add("blocker", name, "%s ring has no stop on its %s face (nothing within 50 mm)" % (ring, side),
                              "no body", "HOUSING_RULES §1: every bearing needs a stop on both sides")
                else:
                    holders[ring] |= set(stop)
                    F.ok(name, "%s ring stop %s" % (ring, side), ", ".join("%s (%.0f%%)" % (fd.short(kk), 100 * c) for kk, c in stop.items()))
        # same body on both rings (bridging the bearing): test the whole side faces of the rings
        b_ = nb["bearing"]
        d1 = b_["d1_approx_mm"] or (nb["d"] + 0.35 * (nb["D"] - nb["d"]))
        D1 = nb["D"] - (d1 - nb["d"])
        full = {"inner": np.linspace(nb["d"] / 2 + 0.4, d1 / 2 - 0.3, 4), "outer": np.linspace(D1 / 2 + 0.3, nb["D"] / 2 - 0.4, 4)}
        for zend, s in ((lo, -1), (hi, +1)):
            touch = {}
            for ring, radii in full.items():
                hits = set()
                for r_ in radii:
                    for a in x_ang:
                        p = O + e * (zend + s * 0.03) + r_ * (math.cos(a) * x + math.sin(a) * y)
                        hits |= set(bodies_at(fd, p, exclude=ks))
                touch[ring] = hits
            both = touch["outer"] & touch["inner"]
            for kk in both:
                F.add("blocker", name, "%s touches BOTH the inner and the outer ring on the %s face (shoulder/spacer bridges the bearing)"
                      % (fd.short(kk), "−z" if s < 0 else "+z"), "contact on both ring faces (inner land d1 ≈ %.1f, outer land D1 ≈ %.1f)" % (d1, D1),
                      "HOUSING_RULES §1 / DIN 5418: a housing shoulder touches only the outer ring, a shaft shoulder only the inner ring")
        # seat & journal support over the width
        for ring, rr, sgn in (("outer", nb["D"] / 2 + 0.05, 1), ("inner", nb["d"] / 2 - 0.05, -1)):
            cov = 0
            npts = 0
            who = defaultdict(int)
            for (z0, z1, k) in zs:
                for f_ in np.linspace(0.1, 0.9, 5):
                    for a in x_ang[::2]:
                        p = O + e * (z0 + f_ * (z1 - z0)) + rr * (math.cos(a) * x + math.sin(a) * y)
                        h = bodies_at(fd, p, exclude=ks)
                        npts += 1
                        if h:
                            cov += 1
                            for kk in h:
                                who[kk] += 1
            frac = cov / npts
            holders[ring + "_seat"] = set(who)
            if frac < 0.95:
                sev = "blocker" if frac < 0.5 else "major"
                F.add(sev, name, "%s ring %s over only %.0f%% of the bearing width (%s)" %
                      (ring, "seated in a bore" if ring == "outer" else "on a journal", 100 * frac,
                       ", ".join(fd.short(kk) for kk in who) or "nothing"),
                      "%.0f%% of B" % (100 * frac), "HOUSING_RULES §1 inner-ring journal: Ø d over the full width B (outer ring likewise in its seat)")
            else:
                F.ok(name, "%s ring support" % ring, "%.0f%% of width on %s" % (100 * frac, ", ".join(fd.short(kk) for kk in who)))
        seat_holders[root] = {"ks": ks, "model": model, "name": name, "O": O, "e": e, "lo": lo, "hi": hi, "nb": nb,
                              "holders": holders}
        # two-point support spacing (rule of thumb) for the body carrying this stack
        if len(ks) >= 2:
            cs = [0.5 * (z0 + z1) for z0, z1, _ in zs]
            sp = max(cs) - min(cs)
            if sp < 1.5 * nb["d"]:
                F.add("minor", name, "bearings of this stack are %.1f mm apart (centres) on Ø%g: below the 1.5 × Ø rule of thumb "
                      "(only a moment-stiff pair if preloaded; HOUSING_RULES itself notes the FD room fits two bearings side by side)"
                      % (sp, nb["d"]), "%.1f mm < %.1f mm" % (sp, 1.5 * nb["d"]),
                      "HOUSING_RULES §1 two-point support (seed 000 p.024 rule 5)")
    return seat_holders


def relative_motion(fd, stacks):
    """pairs of scene bodies that turn relative to each other: the bodies carrying the outer and the inner
    rings of a bearing; in an FD-2 set also the two casing halves (the two largest parts; seed 001: circular
    splines S and D differ by two teeth, so the halves turn relative to each other)."""
    rm = set()
    for st in stacks.values():
        h = st["holders"]
        outer = h.get("outer_seat", set())
        inner = h.get("inner_seat", set())
        for a in outer:
            for b in inner:
                if a != b:
                    rm.add(tuple(sorted((a, b))))
    if fd.family == "FD-2":
        big = sorted(fd.part_of_scene, key=lambda k: -fd.scene[k].vol)[:2]
        if len(big) == 2:
            rm.add(tuple(sorted(big)))
    fd.relmove = rm
    if rm:
        fd.F.ok("assembly", "relative motion", "; ".join("%s ↔ %s" % (fd.short(a), fd.short(b)) for a, b in sorted(rm)))
    return rm


def check_seats(fd, prt, stacks):
    """shoulder diameters, ring grooves, lead-ins for the seats the bearings actually sit in"""
    F = fd.F
    b = prt["ab"]
    nm = prt["name"]
    cat = fd.cat
    sg = seats_and_grooves(b, cat)
    confirmed = []
    if stacks:
        O, e = b.axis
        for seat in sg["seats"]:
            inside = []
            for root, st in stacks.items():
                if not axis_line_match(O, e, st["O"], st["e"]):
                    continue
                bearing = st["nb"]["bearing"]
                dia = seat["dia"]
                if seat["bore"] and not near(dia, bearing["D_mm"], 0.06):
                    continue
                if not seat["bore"] and not near(dia, bearing["d_mm"], 0.06):
                    continue
                zc = np.dot(st["O"] + st["e"] * 0.5 * (st["lo"] + st["hi"]) - O, e)
                half = 0.5 * (st["hi"] - st["lo"])
                if seat["cyl"]["z1"] < zc - half + 0.1 or seat["cyl"]["z0"] > zc + half - 0.1:
                    continue
                inside.append((st, zc - half, zc + half))
            if inside:
                lo = min(x[1] for x in inside)
                hi = max(x[2] for x in inside)
                confirmed.append((seat, inside[0][0], 0.5 * (lo + hi), 0.5 * (hi - lo)))
    for seat, st, zc, half in confirmed:
        bearing = seat["bearing"] if st is None else st["nb"]["bearing"]
        d, D, B, rs = bearing["d_mm"], bearing["D_mm"], bearing["B_mm"], bearing["r_s_min_mm"]
        h = cat.h_min(rs)
        d1 = bearing["d1_approx_mm"]
        what = "%s seat Ø%g (%s, z %.1f…%.1f)" % ("housing" if seat["bore"] else "shaft", seat["dia"], bearing["model"],
                                                   seat["cyl"]["z0"], seat["cyl"]["z1"])
        kinds = [en["kind"] for en in seat["ends"]]
        # which end faces the bearing stack; ends away from the stack are not stops
        # only the seat ends at the bearings' faces are their stops (a longer bore continues past them)
        stops = [en for en in seat["ends"] if st is None or abs(abs(en["z"] - zc) - half) < 1.0]
        if st is not None and len(stops) < 2:
            # the seat cylinder is longer than the stack on one side: that side's stop is not on this part
            pass
        for en in stops:
            if en["kind"] == "shoulder":
                sd = en["shoulder_d"]
                if seat["bore"]:
                    lo_lim = (d1 + 1) if d1 else None
                    hi_lim = D - 2 * h
                    msg = "housing shoulder bore Ø%.2f" % sd
                    if lo_lim is not None and sd <= lo_lim:
                        F.add("blocker", nm, "%s: %s ≤ d1 + 1 = %.1f: the shoulder reaches the inner ring" % (what, msg, lo_lim),
                              "Ø%.2f" % sd, "HOUSING_RULES §1 / DIN 5418: d1 + 1 < shoulder bore ≤ D_a,max = D − 2h = %.1f" % hi_lim)
                    elif sd > hi_lim + 0.01:
                        F.add("major", nm, "%s: %s > D_a,max = %.1f (abutment height below h_min %.1f)" % (what, msg, hi_lim, h),
                              "Ø%.2f" % sd, "DIN 5418 (catalog bearing_abutment_din5418.csv)")
                    else:
                        F.ok(nm, what + " shoulder", "%s within (%s, %.1f]" % (msg, "%.1f" % lo_lim if lo_lim else "d1 not in catalog", hi_lim))
                else:
                    lo_lim = d + 2 * h
                    hi_lim = d1 if d1 else None
                    msg = "shaft shoulder Ø%.2f" % sd
                    if sd < lo_lim - 0.01:
                        F.add("major", nm, "%s: %s < d_a,min = d + 2h = %.1f" % (what, msg, lo_lim), "Ø%.2f" % sd,
                              "DIN 5418 abutment (h_min %.1f for r_s %.1f)" % (h, rs))
                    elif hi_lim is not None and sd > hi_lim:
                        F.add("blocker", nm, "%s: %s > inner-ring land d1 ≈ %.1f: the shoulder reaches the outer ring / seal" % (what, msg, hi_lim),
                              "Ø%.2f" % sd, "HOUSING_RULES §1: shaft shoulder touches only the inner ring (d_a,max ≈ d1 used as proxy)")
                    else:
                        F.ok(nm, what + " shoulder", "%s within [%.1f, %s]" % (msg, lo_lim, "%.1f (d1 proxy)" % hi_lim if hi_lim else "?"))
                if isinstance(en.get("fillet"), float) and en["fillet"] > rs + 1e-3:
                    F.add("major", nm, "%s: shoulder fillet r %.2f > r_s,min %.1f (the ring cannot seat)" % (what, en["fillet"], rs),
                          "r %.2f" % en["fillet"], "HOUSING_RULES §1: r_a ≤ r_s,min or DIN 509 undercut")
            elif en["kind"] == "ring groove":
                kind = "bore" if seat["bore"] else "shaft"
                ring = cat.ring(kind, seat["dia"])
                if ring is None:
                    F.add("minor", nm, "%s: ring groove Ø%.2f×%.2f, no DIN %s row for Ø%g in the catalog" %
                          (what, en["groove_d"], en["groove_w"], "472" if seat["bore"] else "471", seat["dia"]), "-", "DIN 471/472")
                else:
                    errs = []
                    if not near(ring["d2"], en["groove_d"], 0.06):
                        errs.append("groove Ø%.2f vs d2 %.2f" % (en["groove_d"], ring["d2"]))
                    if not near(ring["m"], en["groove_w"], 0.06):
                        errs.append("width %.2f vs m %.2f" % (en["groove_w"], ring["m"]))
                    if en["land"] < ring["n"] - 0.01:
                        errs.append("edge distance %.2f < n %.2f" % (en["land"], ring["n"]))
                    if errs:
                        F.add("major", nm, "%s: retaining-ring groove off DIN %s: %s" % (what, "472" if seat["bore"] else "471", "; ".join(errs)),
                              "; ".join(errs), "DIN 471/472 (catalog retaining_ring_din471_din472.csv)")
                    else:
                        F.ok(nm, what + " ring groove", "Ø%.2f × %.2f, land %.1f ≥ n %.1f (DIN %s)" % (
                            en["groove_d"], en["groove_w"], en["land"], ring["n"], "472" if seat["bore"] else "471"))
            elif en["kind"] == "open":
                pass
        if st is not None:
            pass
        # lead-in at the open end(s) the bearing is mounted through
        opens = [en for en in seat["ends"] if en["kind"] == "open"]
        if opens and all(en.get("leadin") is None for en in opens):
            F.add("major", nm, "%s: open end(s) at z %s have sharp edges, no lead-in chamfer" % (what, ", ".join("%.2f" % en["z"] for en in opens)),
                  "no chamfer", "HOUSING_RULES §4: lead-in chamfers on bearing seats 15–30°")
        for en in opens:
            li = en.get("leadin")
            if isinstance(li, float) and not (14.5 <= li <= 30.5):
                F.add("minor", nm, "%s: lead-in chamfer at z %.2f is %.0f° (rules ask 15–30°)" % (what, en["z"], li),
                      "%.0f° × %.2f" % (li, en.get("leadin_len", 0)), "HOUSING_RULES §4 edges")
        if not any(en["kind"] in ("shoulder",) for en in seat["ends"]):
            F.add("info", nm, "%s: no shoulder on this part at either end (%s); the stops come from other bodies (see bearing-stack rows)"
                  % (what, ", ".join(kinds)), "-", "HOUSING_RULES §1 axial location")
    return sg, confirmed


def check_grooves(fd, prt, sg, holes):
    F = fd.F
    nm = prt["name"]
    cat = fd.cat
    for g in sg["grooves"]:
        m = classify_groove(g, cat)
        if g["type"] == "face":
            desc = "face groove r %.2f…%.2f, depth %.2f, width %.2f (z %.2f)" % (g["r_in"], g["r_out"], g["depth"], g["width"], g["z_top"])
        else:
            desc = "%s groove Ø%.2f in Ø%.2f, depth %.2f, width %.2f (z %.2f…%.2f)" % (g["type"], g["bottom_d"], g["land_d"],
                                                                                     g["depth"], g["width"], g["z0"], g["z1"])
        g["match"] = m[0][0] if m else None
        if not m:
            F.add("info", nm, "groove matches neither DIN 471/472 nor the ISO 3601 gland table: " + desc, desc, "-")
            continue
        std, row, err = m[0]
        if std.startswith("ISO 3601"):
            d2 = row["d2"]
            if g["type"] == "face":
                rng_d, rng_w = (0.70 * d2, 0.80 * d2), (1.3 * d2, 1.5 * d2)
                tab = (row["fd"], row["fw"])
            else:
                rng_d, rng_w = (0.75 * d2, 0.85 * d2), (1.3 * d2, 1.4 * d2)
                tab = (row["rd"], row["rw"])
            bad = []
            if not (rng_d[0] - 0.01 <= g["depth"] <= rng_d[1] + 0.01):
                bad.append("depth %.2f outside %.2f–%.2f" % (g["depth"], *rng_d))
            if not (rng_w[0] - 0.01 <= g["width"] <= rng_w[1] + 0.01):
                bad.append("width %.2f outside %.2f–%.2f" % (g["width"], *rng_w))
            if abs(g["depth"] - tab[0]) > 0.05 or abs(g["width"] - tab[1]) > 0.1:
                bad.append("catalog row %.2f × %.2f" % tab)
            if bad:
                F.add("major" if len(bad) > 1 else "minor", nm, "O-ring gland (%s): %s" % (std, "; ".join(bad)), desc,
                      "HOUSING_RULES §2 / ISO 3601-2 (catalog oring_gland_iso3601.csv)")
            else:
                F.ok(nm, "O-ring gland", "%s: %s" % (std, desc))
            if g["type"] == "face":
                # screws outside the groove: holes opening on the same face
                on_face = [h for h in holes if h["kind_dir"] == "axial" and any(
                    near(z, g["z_top"], 0.05) for (r_, z) in opening_positions(prt["ab"], h).values())]
                if on_face:
                    inside = [h for h in on_face if h["r_axis"] - h["d"] / 2 < g["r_out"]]
                    if inside:
                        F.add("minor", nm, "face O-ring groove (r_out %.2f) is not inside the bolt circle: %d hole(s) on the same face at r %.1f"
                              % (g["r_out"], len(inside), inside[0]["r_axis"]), "r_out %.2f vs holes r %.1f" % (g["r_out"], inside[0]["r_axis"]),
                              "HOUSING_RULES §2: groove inside the bolt circle so that the screws stay dry")
        else:
            F.ok(nm, "ring groove", "%s: %s" % (std, desc))


def _nodeg(s):
    return re.sub(r", θ -?\d+°", "", s)


def hole_faces_with_bottoms(b, holes):
    """face index → (hole, role) including flat bottoms / spot-face floors perpendicular to the hole axis"""
    info = b.face_info()
    adj = b.adj
    out = {}
    for h in holes:
        for fi in h["faces"]:
            out[fi] = (h, "wall")
        rmax = max(s["r"] for s in h["segs"])
        for fi in list(h["faces"]):
            for nb in adj[fi]:
                d = info[nb]
                if nb in out or d["type"] != "plane" or d["normal"] is None:
                    continue
                if abs(abs(np.dot(d["normal"], h["a"])) - 1) > 1e-3:
                    continue
                q = d["bpts"] - h["p0"]
                rr = np.linalg.norm(q - np.outer(q @ h["a"], h["a"]), axis=1)
                if rr.max() <= rmax + 0.02:
                    out[nb] = (h, "bottom")
    return out


def check_walls(fd, prt, holes, h_sample, breaks=frozenset(), ring_faces=None):
    ring_faces = ring_faces or {}
    F = fd.F
    b = prt["ab"]
    nm = prt["name"]
    mat = fd.material
    wmin = WALL_MIN.get(mat, 3.0)
    samples = b.sample_faces(h=h_sample, cap=400)
    per_face_n = defaultdict(int)
    for i, _, _ in samples:
        per_face_n[i] += 1
    info = b.face_info()
    adj = b.adj
    hf = hole_faces_with_bottoms(b, holes)
    # outer envelope: coaxial convex cylinders at the largest radius, or planes parallel to the axis far out
    cyl, pla, con, tor = b.axial_features()
    rmax = max([c["r"] for c in cyl if not c["concave"]] + [0.0])
    O, e = b.axis
    outer = set(c["i"] for c in cyl if not c["concave"] and c["r"] >= rmax - 0.6)
    for d in info:
        if d["type"] == "plane" and d["normal"] is not None and abs(np.dot(d["normal"], e)) < 1e-3:
            r_, z_, _ = b.rz(d["bpts"])
            if r_.min() > 0.6 * rmax:
                outer.add(d["i"])
    groups = {}
    tmin_all = (1e9, None)
    hole_nbrs = {}
    for h in holes:
        s_ = set()
        for fi in h["faces"]:
            s_ |= adj[fi]
        for fi, (hh, role) in hf.items():
            if hh is h:
                s_ |= adj[fi]
        hole_nbrs[id(h)] = s_
    for i, p, n in samples:
        dvec = -n
        hits = b.cast(p, dvec, tmin=2e-4)
        if not hits:
            continue
        t, j, u, v = hits[0]
        if j in adj[i] or (j == i and t < 0.2):
            continue
        nj = b.normal(j, u, v)
        if nj is None or np.dot(nj, dvec) <= 0.0:
            continue
        gi_ = ring_faces.get(i) or ring_faces.get(j)
        if gi_ is not None and not (hf.get(i) or hf.get(j)):
            n_ = gi_
            if t < n_ - 1e-3:
                fa, fb = sorted([_nodeg(b.describe_face(i)), _nodeg(b.describe_face(j))])
                key = ("ring-groove land", fa, fb)
                g = groups.setdefault(key, {"t": t, "n": 0, "lim": n_, "kind": "ring-groove land", "at_break": (i in breaks) or (j in breaks),
                                            "rule": "DIN 471/472 least edge distance n = %.1f" % n_, "desc": "%s ↔ %s" % (fa, fb),
                                            "area": 0.0, "p": p, "pairs": set()})
                g["pairs"].add((min(i, j), max(i, j)))
                g["area"] += info[i]["area"] / max(per_face_n[i], 1)
                if t < g["t"]:
                    g["t"], g["p"] = t, p
            if t < tmin_all[0]:
                tmin_all = (t, (i, j, p))
            continue
        hi_, hj_ = hf.get(i), hf.get(j)
        if hi_ and hj_ and hi_[0] is hj_[0]:
            continue  # across one hole's own faces (e.g. counterbore floor to the hole's far end)
        if (hi_ and j in hole_nbrs[id(hi_[0])]) or (hj_ and i in hole_nbrs[id(hj_[0])]):
            continue  # the surface the hole enters through: rays near the entry graze it, not a ligament
        at_break = (i in breaks) or (j in breaks)
        if (hi_ and hi_[1] == "bottom") or (hj_ and hj_[1] == "bottom"):
            hh = (hi_ or hj_)[0]
            rule, lim = "floor under a blind hole ≥ 3 mm (HOUSING_RULES §4)", 3.0
            kind = "floor"
        elif hi_ or hj_:
            ds = []
            for x in (hi_, hj_):
                if x:
                    hh = x[0]
                    dthr = hh["thread"]["d"] if hh.get("thread") else hh["d"]
                    ds.append((dthr, hh))
            dthr, hh = max(ds, key=lambda z: z[0])
            if hh["kind"] == "port":
                lim = max(3.0, 0.5 * dthr)
                rule = "port ligament ≥ max(3 mm, 0.5·d) (HOUSING_RULES §3)"
            else:
                lim = max(2.0, 0.5 * dthr)
                rule = "ligament ≥ 0.5·d and ≥ 2 mm (HOUSING_RULES §4)"
            kind = "ligament"
            other = j if hi_ else i
            if other in outer and not (hi_ and hj_):
                # centre-to-edge distance 1.5·d
                hole_r = hh["d"] / 2 if (hf.get(i if hi_ else j)[1] == "wall") else None
                if hole_r is not None and hh["kind_dir"] == "axial":
                    seg_r = None
                    fi_h = i if hi_ else j
                    for s in hh["segs"]:
                        if fi_h in s["i"]:
                            seg_r = s["r"]
                    if seg_r is not None and abs(seg_r - hh["d"] / 2) < 1e-3:
                        cd = t + seg_r
                        key = ("edge", _nodeg(b.describe_face(fi_h)), _nodeg(b.describe_face(other)))
                        g = groups.setdefault(key, {"t": cd, "n": 0, "lim": 1.5 * dthr, "kind": "edge",
                                                    "rule": "hole centre ≥ 1.5·d from the outer edge (HOUSING_RULES §4)",
                                                    "desc": "%s → %s" % (_nodeg(b.describe_face(fi_h)), _nodeg(b.describe_face(other))),
                                                    "area": 0.0, "p": p})
                        g["t"] = min(g["t"], cd)
                        g["n"] += 1
                        g.setdefault("holes", set()).add(fi_h)
        else:
            lim, rule, kind = wmin, "machined wall ≥ %.0f mm for %s (HOUSING_RULES §4)" % (wmin, mat), "wall"
        if t < tmin_all[0]:
            tmin_all = (t, (i, j, p))
        if t >= lim - 1e-3:
            continue
        fa, fb = sorted([_nodeg(b.describe_face(i)), _nodeg(b.describe_face(j))])
        key = (kind, fa, fb)
        g = groups.setdefault(key, {"t": t, "n": 0, "lim": lim, "kind": kind, "rule": rule, "at_break": at_break,
                                    "desc": "%s ↔ %s" % (fa, fb), "area": 0.0, "p": p, "pairs": set()})
        g["pairs"].add((min(i, j), max(i, j)))
        g["n"] += 1
        g["area"] += info[i]["area"] / max(per_face_n[i], 1)
        if t < g["t"]:
            g["t"], g["p"] = t, p
    for key, g in sorted(groups.items(), key=lambda kv: kv[1]["t"]):
        if g["kind"] == "edge":
            nh = len(g.get("holes", ()))
            if g["t"] < g["lim"] - 1e-3:
                F.add("major", nm, "hole too close to the outer edge: %s%s" % (g["desc"], " (×%d holes)" % nh if nh > 1 else ""),
                      "centre distance %.2f mm < %.2f" % (g["t"], g["lim"]), g["rule"])
            else:
                F.ok(nm, "edge distance", "%s: %.2f ≥ %.2f" % (g["desc"], g["t"], g["lim"]))
            continue
        r_, z_, th_ = b.rz(np.array([g["p"]]))
        where = "at r %.1f z %.1f" % (r_[0], z_[0])
        npairs = len(g.get("pairs", ()))
        mult = " (×%d similar)" % npairs if npairs > 1 else ""
        note = ""
        if g["t"] < 1.0:
            sev = "blocker"
        elif g["at_break"]:
            sev, note = "minor", " — only where a chamfer/fillet cuts into the wall"
        elif g["area"] < 1.0:
            sev, note = "minor", " — local"
        else:
            sev = "major"
        F.add(sev, nm, "thin %s: %s%s %s; thin region ≈ %.1f mm² (ray sampling)%s" % (g["kind"], g["desc"], mult, where, g["area"], note),
              "%.2f mm < %.1f" % (g["t"], g["lim"]), g["rule"])
    if tmin_all[1] is not None:
        i, j, p = tmin_all[1]
        F.ok(nm, "minimum ray thickness", "%.2f mm between %s and %s (%d rays, spacing ≈ %.1f mm; thickness along the inward normal, "
             "so a true minimum between two samples can be lower by up to ≈ spacing²/(8·R) on curved faces)"
             % (tmin_all[0], b.describe_face(i), b.describe_face(j), len(samples), h_sample))


def check_holes(fd, prt, holes):
    F = fd.F
    nm = prt["name"]
    b = prt["ab"]
    mat = fd.material
    k_eng = ENGAGE_K.get(mat, 1.0)
    grouped = defaultdict(list)
    for h in holes:
        key = (h["kind"], h["thread"]["thread"] if h.get("thread") else None, round(h["d"], 2), round(h["drill_len"], 1),
               h["kind_dir"], round(h["r_axis"], 1), tuple(sorted((k, v["kind"]) for k, v in h["ends"].items())))
        grouped[key].append(h)
    for key, hs in grouped.items():
        h = hs[0]
        n = len(hs)
        lab = "%d× %s %s Ø%.2f (%s, r %.1f, z %.1f)" % (n, h["kind"], h["thread"]["thread"] if h.get("thread") else "",
                                                         h["d"], h["kind_dir"], h["r_axis"], h["z"])
        if h["wall_broken"]:
            F.add("major", nm, "%s: hole wall is interrupted (breaks into another feature)" % lab, "cylinder span %.0f°" %
                  math.degrees(min(s["uspan"] for s in h["segs"])), "walls/ligaments HOUSING_RULES §4")
        if h["kind"] == "tapped":
            th = h["thread"]
            d, Pp = th["d"], th["P"]
            blind = [v for v in h["ends"].values() if v["kind"] == "blind"]
            need_eng = k_eng * d
            if blind:
                need = need_eng + 3 * Pp
                if h["drill_len"] + 1e-3 < need:
                    F.add("major", nm, "%s: drilled depth %.2f < engagement %.1f·d + 3P = %.2f" % (lab, h["drill_len"], k_eng, need),
                          "%.2f mm" % h["drill_len"], "HOUSING_RULES §4 thread engagement (VDI 2230 guidance; %s)" % mat)
                else:
                    F.ok(nm, lab, "drilled %.2f ≥ %.2f (%.1f·d + 3P)" % (h["drill_len"], need, k_eng))
                fl = blind[0]["floor"]
                if fl is not None:
                    if fl < 0.3:
                        F.add("blocker", nm, "%s: blind hole breaks through (floor %.2f mm)" % (lab, fl), "%.2f mm" % fl,
                              "floor under blind holes ≥ 3 mm (HOUSING_RULES §4)")
                    elif fl < 3.0 - 1e-3:
                        F.add("major", nm, "%s: floor under the blind hole %.2f mm" % (lab, fl), "%.2f mm < 3" % fl,
                              "floor under blind holes ≥ 3 mm (HOUSING_RULES §4)")
                if not h["drill_point"] and blind[0].get("bottom") == "plane":
                    F.add("minor", nm, "%s: flat-bottomed blind tapped hole (no 118° drill point modelled)" % lab, "flat bottom",
                          "HOUSING_RULES §4: blind tapped depth drilled 118°")
            else:
                if h["drill_len"] + 1e-3 < need_eng:
                    F.add("major", nm, "%s: through-tapped length %.2f < %.1f·d = %.2f" % (lab, h["drill_len"], k_eng, need_eng),
                          "%.2f mm" % h["drill_len"], "HOUSING_RULES §4 thread engagement")
                ops = opening_positions(b, h)
                F.add("minor", nm, "%s: tapped THROUGH hole (opens at %s); if wetted it needs sealing thread-locker" %
                      (lab, "; ".join("r %.1f z %.1f" % v for v in ops.values())), "through",
                      "seed 000 p.028 (HOUSING_RULES §2): sealing thread-locker on tapped through holes")
            if h["countersink"] is None:
                F.add("minor", nm, "%s: no 90° countersink at the tapped entry" % lab, "none", "HOUSING_RULES §4: countersink the entry 90° to the major Ø")
            elif h["countersink"] + 0.05 < d:
                F.add("minor", nm, "%s: countersink Ø%.2f smaller than the major Ø%g" % (lab, h["countersink"], d),
                      "Ø%.2f" % h["countersink"], "HOUSING_RULES §4")
        elif h["kind"] == "port":
            th = h["thread"]
            if h["counterbore"] is None:
                F.add("major", nm, "%s: no spot face at the port entry" % lab, "none",
                      "HOUSING_RULES §3: spot face of the plug-collar Ø (+1 mm)")
            elif h["counterbore"]["d"] + 1e-3 < th["collar"] + 1:
                F.add("major", nm, "%s: spot face Ø%.2f < collar %g + 1" % (lab, h["counterbore"]["d"], th["collar"]),
                      "Ø%.2f" % h["counterbore"]["d"], "HOUSING_RULES §3 / DIN 908 (catalog plug_port_din908_din7603.csv)")
            else:
                F.ok(nm, lab + " spot face", "Ø%.2f ≥ %g" % (h["counterbore"]["d"], th["collar"] + 1))
            if h["drill_len"] + 1e-3 < 1.5 * th["d"]:
                F.add("major", nm, "%s: thread length %.2f < 1.5·d = %.1f (DIN 908 plug thread length %g fits)" %
                      (lab, h["drill_len"], 1.5 * th["d"], th["thread_length"]), "%.2f mm" % h["drill_len"],
                      "HOUSING_RULES §3: the thread is 1.5 × d deep")
            else:
                F.ok(nm, lab + " thread length", "%.2f ≥ %.1f" % (h["drill_len"], 1.5 * th["d"]))
        elif h["kind"] == "clearance":
            th = h["thread"]
            if th.get("fit") != "medium":
                F.add("info", nm, "%s: clearance hole is ISO 273 %s (rules ask medium)" % (lab, th.get("fit")), "Ø%.2f" % h["d"], "HOUSING_RULES §4")
            cb = h["counterbore"]
            if cb:
                head = fd.cat.heads.get(th["thread"])
                ref = DIN974_CB.get(th["thread"])
                if head and cb["d"] < head["dk"] + 0.2:
                    F.add("major", nm, "%s: counterbore Ø%.2f does not clear the ISO 4762 head dk %g" % (lab, cb["d"], head["dk"]),
                          "Ø%.2f" % cb["d"], "DIN 974-1 counterbores")
                elif ref and abs(cb["d"] - ref) > 0.05:
                    F.add("minor", nm, "%s: counterbore Ø%.2f differs from DIN 974-1 Ø%g (probe constant, not in the catalog)" % (lab, cb["d"], ref),
                          "Ø%.2f" % cb["d"], "HOUSING_RULES §4: DIN 974-1 counterbores")
                if head and cb["depth"] + 1e-3 < head["k"] + 0.5:
                    F.add("minor" if cb["depth"] >= head["k"] else "major", nm,
                          "%s: counterbore depth %.2f < k + 0.5 = %.1f" % (lab, cb["depth"], head["k"] + 0.5),
                          "%.2f mm" % cb["depth"], "HOUSING_RULES §4: counterbore depth k + 0.5")
                else:
                    F.ok(nm, lab + " counterbore", "Ø%.2f depth %.2f" % (cb["d"], cb["depth"]))
        elif h["kind"].startswith("tapped (modelled"):
            F.add("info", nm, "%s: hole at a thread's major Ø (thread modelled at nominal size?)" % lab, "Ø%.2f" % h["d"], "-")
        else:
            F.add("info", nm, "%s: hole not matched to a tap drill / clearance / port table (%s)" % (lab, ", ".join(h["alternatives"]) or "no match"),
                  "Ø%.2f, length %.2f" % (h["d"], h["drill_len"]), "-")


def check_edges(fd, prt):
    F = fd.F
    nm = prt["name"]
    b = prt["ab"]
    es, br = edge_analysis(b)
    info = b.face_info()
    sharp = [e for e in es if e["convex"] and e["angle"] > 75]
    Ls = sum(e["L"] for e in sharp)
    Lb = sum(x["L"] for x in br)
    tot = Ls + Lb
    frac = Ls / tot if tot else 0.0
    cats = defaultdict(lambda: [0, 0.0])
    for e in sharp:
        t = [info[f]["type"] for f in e["faces"]]
        co = [("cyl" == info[f]["type"] and b.coaxial(info[f])) for f in e["faces"]]
        hole = [("cyl" == info[f]["type"] and not b.coaxial(info[f]) and info[f]["concave"]) for f in e["faces"]]
        c = "hole entries" if any(hole) else ("coaxial bore/diameter edges" if any(co) else "other outer edges")
        cats[c][0] += 1
        cats[c][1] += e["L"]
    detail = "; ".join("%s %d (%.0f mm)" % (k, v[0], v[1]) for k, v in cats.items())
    if frac > 0.05:
        F.add("minor", nm, "%.0f%% of convex corner length is a sharp unbroken edge (%d edges: %s); %d chamfer/fillet faces model the breaks"
              % (100 * frac, len(sharp), detail, len(br)), "%.0f mm sharp of %.0f mm" % (Ls, tot),
              "HOUSING_RULES §4 / ISO 13715: 0.5 × 45° on outer edges (or drawing note ISO 13715 −0.3 +0.3)")
    else:
        F.ok(nm, "edge breaks", "%.0f%% sharp convex length" % (100 * frac))
    return es, br


def check_mating_leadins(fd, prt):
    """coaxial cylinders of the part in contact with another body (pilots, seats, seal bores, journals):
    their entry edges should carry a lead-in chamfer"""
    F = fd.F
    b = prt["ab"]
    nm = prt["name"]
    if not fd.scene or prt["scene"] is None:
        return
    cyl, pla, con, tor = b.axial_features()
    O, e = b.axis
    x, y = perp_basis(e)
    me = prt["scene"]
    for c in cyl:
        L = c["z1"] - c["z0"]
        if L < 0.8 or not c["full"]:
            continue
        sgn = 1 if c["concave"] else -1  # outward normal direction radially: concave → towards axis
        rr = c["r"] - 0.04 if c["concave"] else c["r"] + 0.04
        who = defaultdict(int)
        for zf in (0.3, 0.5, 0.7):
            for a in np.radians([11, 101, 191, 281]):
                p = O + e * (c["z0"] + zf * L) + rr * (math.cos(a) * x + math.sin(a) * y)
                for k in bodies_at(fd, p, exclude=(me,)):
                    who[k] += 1
        mates = [k for k, v in who.items() if v >= 6]
        if not mates:
            continue
        what = "%s Ø%.2f (z %.1f…%.1f) mating with %s" % ("bore" if c["concave"] else "spigot/journal", 2 * c["r"], c["z0"], c["z1"],
                                                          ", ".join(fd.short(k) for k in mates))
        kinds = [fd.neigh.get(k, {}).get("kind", "part") for k in mates]
        ends = [seat_end(b, fd.cat, c, zend, s, c["concave"], cyl, pla, con, tor) for zend, s in ((c["z0"], -1), (c["z1"], +1))]
        opens = [en for en in ends if en["kind"] == "open"]
        if not opens:
            continue
        sev = "major"
        if all(en.get("leadin") is None for en in opens):
            F.add(sev, nm, "%s: no lead-in chamfer at its open end(s) z %s (sharp edges)" % (what, ", ".join("%.2f" % en["z"] for en in opens)),
                  "sharp edge", "HOUSING_RULES §4: lead-in chamfers on pilots, bearing seats and seal bores (15–30°)")
        else:
            li = [en.get("leadin") for en in opens if en.get("leadin") is not None]
            if any(k == "lip seal" for k in kinds) and isinstance(li[0], float) and not (14.5 <= li[0] <= 30.5):
                F.add("minor", nm, "%s: lead-in %.0f° (seal bores 15–20°, rules 15–30°)" % (what, li[0]), "%.0f°" % li[0], "HOUSING_RULES §2/§4")
            else:
                F.ok(nm, what, "lead-in %s" % ", ".join(("%.0f°" % x) if isinstance(x, float) else str(x) for x in li))


def check_seals_orings(fd):
    F = fd.F
    parts_idx = set(fd.part_of_scene)
    # relative motion: FD-2 casing halves (the two largest parts) turn relative to each other (seed 001: S and D
    # splines differ by two teeth); bearings separate the bodies on their outer and inner rings.
    relmove = fd.relmove
    for k, n in fd.neigh.items():
        sb = fd.scene[k]
        if n["kind"] == "O-ring":
            sb.find_axis()
            O, e = sb.axis
            x, y = perp_basis(e)
            lab0 = n["label"]
            if "rin" not in n:
                F.add("info", lab0, "O-ring modelled as a torus: squeeze and contacts not measured by this probe", "-", "-")
                continue
            rin, rout, z0, z1 = n["rin"], n["rout"], n["z0"], n["z1"]
            touch = defaultdict(int)
            probes = []
            for a in np.radians([9, 99, 189, 279]):
                rv = math.cos(a) * x + math.sin(a) * y
                zm, rm = 0.5 * (z0 + z1), 0.5 * (rin + rout)
                probes += [O + e * zm + (rin - 0.05) * rv, O + e * zm + (rout + 0.05) * rv,
                           O + e * (z0 - 0.05) + rm * rv, O + e * (z1 + 0.05) + rm * rv]
            for p in probes:
                for kk in bodies_at(fd, p, exclude=(k,)):
                    touch[kk] += 1
            touching = sorted(touch, key=lambda kk: -touch[kk])
            d2 = n["d2"]
            space = (rout - rin) if "radial" in n["model"] else (z1 - z0)
            sq = 1 - space / d2
            lab = "%s touching %s" % (lab0, ", ".join(fd.short(kk) for kk in touching) or "nothing")
            F.ok(lab, "squeeze", "modelled as its squeezed section %.2f × %.2f: gland space %.2f for d2 %.2f → squeeze %.0f%%"
                 % (rout - rin, z1 - z0, space, d2, 100 * sq))
            if not (0.14 <= sq <= 0.31):
                F.add("major", lab, "O-ring squeeze %.0f%% outside 15–30%%" % (100 * sq), "%.0f%%" % (100 * sq),
                      "HOUSING_RULES §2 (ISO 3601-2 glands: radial 15–25 %, face 20–30 %)")
            pp = [kk for kk in touching if kk in parts_idx]
            for a_ in pp:
                for b_ in pp:
                    if a_ < b_ and (a_, b_) in relmove:
                        F.add("major", lab, "O-ring seals the joint between %s and %s, which turn relative to each other (FD running gap): "
                              "a static ISO 3601 gland (%.0f%% squeeze) used as a rotary seal" % (fd.short(a_), fd.short(b_), 100 * sq),
                              "rotary O-ring, squeeze %.0f%%" % (100 * sq),
                              "HOUSING_RULES §2: close the running gap with a lip seal (bore + journal overlapping ≥ b) or a V-ring/axial lip")
        elif n["kind"] == "lip seal":
            sb.find_axis()
            O, e = sb.axis
            x, y = perp_basis(e)
            z0, z1 = n["z0"], n["z1"]
            for ring, rr in (("journal", n["d1"] / 2 - 0.05), ("bore", n["d2"] / 2 + 0.05)):
                cov, npts, who = 0, 0, defaultdict(int)
                for f_ in np.linspace(0.1, 0.9, 5):
                    for a in np.radians([3, 93, 183, 273]):
                        p = O + e * (z0 + f_ * (z1 - z0)) + rr * (math.cos(a) * x + math.sin(a) * y)
                        hh = bodies_at(fd, p, exclude=(k,))
                        npts += 1
                        if hh:
                            cov += 1
                            for kk in hh:
                                who[kk] += 1
                lab = "lip seal %g×%g×%g" % (n["d1"], n["d2"], n["b"])
                if cov / npts < 0.8:
                    F.add("major", lab, "seal %s covered over only %.0f%% of b (%s)" % (ring, 100 * cov / npts, ", ".join(fd.short(kk) for kk in who) or "none"),
                          "%.0f%%" % (100 * cov / npts), "HOUSING_RULES §2: lip seal on a journal of d1 / in a bore of d2 over its width")
                else:
                    F.ok(lab, ring, "%.0f%% covered by %s" % (100 * cov / npts, ", ".join(fd.short(kk) for kk in who)))
            # seal bore depth ≥ b + 0.3 in the part holding the outer diameter
            for kk in parts_idx:
                pb = fd.scene[kk]
                if pb.axis is None or not axis_line_match(pb.axis[0], pb.axis[1], O, e):
                    continue
                cyl, pla, con, tor = pb.axial_features()
                zc = np.dot(O + e * 0.5 * (z0 + z1) - pb.axis[0], pb.axis[1])
                for c in cyl:
                    if c["concave"] and near(2 * c["r"], n["d2"], 0.06) and c["z0"] - 0.1 <= zc <= c["z1"] + 0.1:
                        L = c["z1"] - c["z0"]
                        if L + 1e-3 < n["b"] + 0.3:
                            F.add("major", fd.short(kk), "seal bore Ø%g is %.2f deep < b + 0.3 = %.1f" % (n["d2"], L, n["b"] + 0.3),
                                  "%.2f mm" % L, "HOUSING_RULES §2 (ISO 6194 / DIN 3760)")
                        else:
                            F.ok(fd.short(kk), "seal bore Ø%g depth" % n["d2"], "%.2f ≥ %.1f" % (L, n["b"] + 0.3))
    # FD running gap without any seal bodies near it is reported by the oil check


def check_static_joints(fd):
    """flange-face contacts between a part and another body (not fasteners, bearings, seals, rings):
    is there an O-ring body touching both?"""
    F = fd.F
    skip = {"screw", "plug", "bearing", "lip seal", "O-ring", "retaining ring"}
    orings = [k for k, n in fd.neigh.items() if n["kind"] == "O-ring"]
    oring_touch = {}
    for k in orings:
        sb = fd.scene[k]
        lo, hi = sb.bb
        near_ = set()
        for kk, ob in enumerate(fd.scene):
            if kk != k and boxes_overlap((lo - 0.2, hi + 0.2), ob.bb):
                from OCP.BRepExtrema import BRepExtrema_DistShapeShape
                dss = BRepExtrema_DistShapeShape(sb.solid, ob.solid)
                if dss.IsDone() and dss.Value() < 0.05:
                    near_.add(kk)
        oring_touch[k] = near_
    done = set()
    for prt in fd.parts:
        if prt["scene"] is None:
            continue
        me = prt["scene"]
        b = prt["ab"]
        O, e = b.axis
        x, y = perp_basis(e)
        cyl, pla, con, tor = b.axial_features()
        for p in pla:
            if p["rmax"] - p["rmin"] < 1.0:
                continue
            hits = defaultdict(int)
            n = 0
            for rf in (0.25, 0.5, 0.75):
                r_ = p["rmin"] + rf * (p["rmax"] - p["rmin"])
                for a in np.radians(np.arange(0, 360, 30) + 4):
                    q = O + e * (p["z"] + p["nz"] * 0.05) + r_ * (math.cos(a) * x + math.sin(a) * y)
                    if not b.inside(O + e * (p["z"] - p["nz"] * 0.05) + r_ * (math.cos(a) * x + math.sin(a) * y)):
                        continue  # a hole in the face
                    n += 1
                    for kk in bodies_at(fd, q, exclude=(me,)):
                        hits[kk] += 1
            for kk, c in hits.items():
                if n == 0 or c < 0.5 * n or fd.neigh.get(kk, {}).get("kind") in skip:
                    continue
                key = tuple(sorted((me, kk)))
                if key in done:
                    continue
                done.add(key)
                sealed = [k for k, t in oring_touch.items() if me in t and kk in t]
                what = "flange joint %s ↔ %s (face z %.1f, r %.1f…%.1f)" % (prt["name"], fd.short(kk), p["z"], p["rmin"], p["rmax"])
                if sealed:
                    F.ok(prt["name"], "static joint", what + " carries " + fd.short(sealed[0]))
                    continue
                if fd.family == "GH":
                    F.add("major", prt["name"], what + ": no O-ring in the joint", "no O-ring",
                          "HOUSING_RULES §2 GH input: the flange mating face gets an O-ring (seed 000 table 028-1)")
                else:
                    F.add("minor", prt["name"], what + ": no O-ring in the model — needs sealant (not visible in geometry)", "no O-ring",
                          "seed 000 p.028 (HOUSING_RULES §2): O-ring or sealant on flange faces and fits")
    if fd.family == "GH" and not any(n["kind"] == "lip seal" for n in fd.neigh.values()):
        F.add("info", "assembly", "no shaft seal in the motor adapter / review assembly: acceptable only if the motor has its own shaft seal",
              "no lip seal body", "HOUSING_RULES §2 GH input (table 028-1)")


def check_screws(fd):
    F = fd.F
    rows = defaultdict(list)
    for k, n in fd.neigh.items():
        if n["kind"] != "screw":
            continue
        sb = fd.scene[k]
        sb.find_axis()
        cyl, pla, con, tor = sb.axial_features()
        shank = [c for c in cyl if not c["concave"] and near(2 * c["r"], n["shank_d"], 0.01)]
        if not shank:
            continue
        s0 = min(c["z0"] for c in shank)
        s1 = max(c["z1"] for c in shank)
        head = [c for c in cyl if not c["concave"] and c["r"] > n["shank_d"] / 2 + 0.5]
        hz = np.mean([0.5 * (c["z0"] + c["z1"]) for c in head]) if head else s0
        tip_dir = 1 if abs(s1 - hz) > abs(s0 - hz) else -1
        tip = s1 if tip_dir > 0 else s0
        O, e = sb.axis
        eng = []
        for kk, ob in enumerate(fd.scene):
            if kk == k or ob.bb is None:
                continue
            lo, hi = ob.bb
            pmid = O + e * 0.5 * (s0 + s1)
            if not boxes_overlap((np.minimum(O + e * s0, O + e * s1) - 1, np.maximum(O + e * s0, O + e * s1) + 1), ob.bb):
                continue
            for d in ob.face_info():
                if d["type"] != "cyl" or not d["concave"] or not near(d["r"], n["shank_d"] / 2, 0.06):
                    continue
                if not axis_line_match(O, e, d["axis_p"], unit(d["axis_d"]), tol=0.05):
                    continue
                t = (d["bpts"] - O) @ e
                ov = min(s1, t.max()) - max(s0, t.min())
                if ov > 0:
                    # gap between the screw tip and the hole's far end
                    far = t.max() if tip_dir > 0 else t.min()
                    eng.append((kk, ov, (far - tip) * tip_dir, t.min(), t.max()))
        key = (n["thread"],)
        rows[key].append((k, n, eng))
    for key, lst in rows.items():
        for k, n, eng in lst[:1] + [x for x in lst[1:] if True]:
            pass
        # summarise per thread and per tapped body
        summ = defaultdict(list)
        for k, n, eng in lst:
            if not eng:
                summ[("none",)].append(k)
            for (kk, ov, tipgap, a, b) in eng:
                summ[(kk, round(ov, 2), round(tipgap, 1))].append(k)
        for sk, ks in summ.items():
            n = fd.neigh[ks[0]]
            lab = "%d× screw %s" % (len(ks), n["thread"])
            if sk != ("none",) and sk[0] in fd.part_of_scene:
                lab += " in " + fd.short(sk[0])
            if sk == ("none",):
                F.add("info", lab, "no tapped hole of the shank Ø%.2f found coaxial with the screw (engagement not measured)" % n["shank_d"],
                      "-", "HOUSING_RULES §4 thread engagement")
                continue
            kk, ov, tipgap = sk
            mat = fd.material if kk in fd.part_of_scene else "steel"
            need = ENGAGE_K.get(mat, 1.0) * n["d"]
            if ov + 1e-3 < need:
                F.add("major", lab, "thread engagement in %s %.2f mm < %.2g·d = %.1f (%s%s); measured as the overlap of the screw with the "
                      "full-diameter tapped bore (entry countersink excluded)" % (fd.short(kk), ov, ENGAGE_K.get(mat, 1.0), need, mat,
                      "" if kk in fd.part_of_scene else ", assumed"), "%.2f mm" % ov, "HOUSING_RULES §4 (VDI 2230 guidance)")
            else:
                F.ok(lab, "engagement", "%.1f mm in %s ≥ %.1f" % (ov, fd.short(kk), need))
            if tipgap < n["P"]:
                F.add("major" if tipgap >= 0 else "blocker", lab, "screw tip %.2f mm from the end of the tapped bore in %s (run-out 3P = %.1f)" %
                      (tipgap, fd.short(kk), 3 * n["P"]), "%.2f mm" % tipgap, "HOUSING_RULES §4: blind tapped depth = engagement + 3P")


def check_port_access(fd, prt, holes):
    F = fd.F
    nm = prt["name"]
    b = prt["ab"]
    if prt["scene"] is None:
        return
    O, e = b.axis
    for h in holes:
        if h["kind"] != "port":
            continue
        ops = opening_positions(b, h)
        if not ops:
            continue
        # outer end = the one with the larger radius (radial) or with the spot face
        sgn = max(ops, key=lambda s: ops[s][0]) if h["kind_dir"] == "radial" else list(ops)[0]
        t_end = max(s["t1"] for s in h["segs"]) if sgn > 0 else min(s["t0"] for s in h["segs"])
        q = h["p0"] + t_end * h["a"]
        d = sgn * h["a"]
        blocked = None
        for kk, ob in enumerate(fd.scene):
            if kk == prt["scene"]:
                continue
            nbk = fd.neigh.get(kk, {})
            if nbk.get("kind") == "plug":
                ob.find_axis()
                if axis_line_match(ob.axis[0], ob.axis[1], h["p0"], h["a"], tol=0.1):
                    continue
            hh = ob.cast(q + d * 0.05, d, tmin=1e-4, tmax=300)
            if hh and (blocked is None or hh[0][0] < blocked[0]):
                blocked = (hh[0][0], kk)
        lab = "port %s (θ %.0f°, z %.1f)" % (h["thread"]["thread"], h["theta"], h["z"])
        if blocked:
            F.add("major", nm, "%s: straight tool path from outside blocked by %s at %.1f mm" % (lab, fd.short(blocked[1]), blocked[0]),
                  "%.1f mm" % blocked[0], "HOUSING_RULES §3: reachable with the machine assembled")
        else:
            F.ok(nm, lab + " access", "straight path along the port axis is free (within the modelled bodies)")
        inner = [v for s_, v in ops.items() if s_ != sgn]
        if inner and fd.A is not None and fd.family == "FD-2" and fd.lubrication == "oil":
            r_in = inner[0][0]
            h["r_inner"] = r_in
            if r_in + 1e-3 < fd.A:
                F.add("minor", nm, "%s opens into the cavity at r %.1f < oil level A %.0f: cannot serve as level port" % (lab, r_in, fd.A),
                      "r %.1f" % r_in, "HOUSING_RULES §3 positions (datum: A below the axis, horizontal axis — assumed)")
            else:
                F.ok(nm, lab + " radius", "opens into the cavity at r %.1f ≥ A %.0f (can serve as fill/level port when turned)" % (r_in, fd.A))


def check_mass(fd):
    F = fd.F
    rho = DENSITY.get(fd.material)
    assumed = ""
    if rho is None:
        rho = DENSITY["steel"]
        assumed = " (material '%s' unknown: steel assumed)" % fd.material
    tot = 0.0
    masses = {}
    for prt in fd.parts:
        if prt["body"] is None:
            continue
        m = prt["body"].vol * rho / 1e6
        masses[prt["name"]] = m
        tot += m
        F.ok(prt["name"], "mass", "%.3f kg (V %.0f cm³ × %.2f g/cm³ %s)%s" % (m, prt["body"].vol / 1e3, rho, fd.material, assumed))
        if m < 0.01:
            F.add("major", prt["name"], "implausibly small mass", "%.4f kg" % m, "plausibility")
    ref = None
    if fd.family == "FD-2" and fd.size in fd.cat.fd0:
        m0 = _f(fd.cat.fd0[fd.size]["mass_kg"])
        m2 = _f(fd.cat.fd2[fd.size]["mass_kg"])
        ref = (m0, m2)
        ratio = tot / max(m0 - m2, 1e-6)
        msg = ("generated FD-2 parts weigh %.2f kg in total; the catalog FD-%d-0 unit (with its own casing and bearings) weighs %.1f kg "
               "and the FD-2 component set %.1f kg, so a catalog-like housing is ≈ %.1f kg: ratio %.1f×" % (tot, fd.size, m0, m2, m0 - m2, ratio))
        if ratio > 2.0:
            F.add("minor", "all parts", msg, "%.2f kg" % tot, "mass plausibility (tables 311-1 / 312-1)")
        else:
            F.ok("all parts", "mass plausibility", msg)
    elif fd.family == "FD-0" and fd.size in fd.cat.fd0:
        m0 = _f(fd.cat.fd0[fd.size]["mass_kg"])
        for k, m in masses.items():
            if m > m0:
                F.add("minor", k, "part heavier than the whole FD-%d-0 unit it drives (%.1f kg)" % (fd.size, m0), "%.2f kg" % m, "mass plausibility (311-1)")
            else:
                F.ok(k, "mass plausibility", "%.2f kg vs FD-%d-0 unit %.1f kg" % (m, fd.size, m0))
    return masses, tot


# ----------------------------------------------------------------------------------------------
# oil: flood fill on planar sections through the axis
# ----------------------------------------------------------------------------------------------
def oil_check(fd, outdir, extra_angles=(), step=15, ports=()):
    from scipy import ndimage
    F = fd.F
    A = fd.A
    if fd.main_axis is None or A is None:
        return
    O, e = fd.main_axis
    x, y = perp_basis(e)
    corners = []
    for sb in fd.scene:
        lo, hi = sb.bb
        for cx in (lo[0], hi[0]):
            for cy in (lo[1], hi[1]):
                for cz in (lo[2], hi[2]):
                    corners.append([cx, cy, cz])
    corners = np.array(corners)
    w = (corners - O) @ e
    rr = np.linalg.norm((corners - O) - np.outer(w, e), axis=1)
    R = rr.max() + 4
    wmin, wmax = w.min() - 4, w.max() + 4
    px = max(0.08, (wmax - wmin) / 1800.0, 2 * R / 1800.0)
    nu, nw = int(math.ceil(2 * R / px)), int(math.ceil((wmax - wmin) / px))
    umin = -R
    ug = umin + (np.arange(nu) + 0.5) * px
    perm = {k for k, n in fd.neigh.items() if n["kind"] == "bearing"}
    seal_labels = {k + 1 for k, n in fd.neigh.items() if n["kind"] in ("O-ring", "lip seal", "plug")}
    moving_pairs = {(a + 1, b + 1) for a, b in getattr(fd, "relmove", set())}
    strict = True
    # housing envelope (parts only) for "where it leaves"
    angles = sorted({float(a) % 180 for a in list(np.arange(0, 180, step)) + list(extra_angles)})
    Lbig = float(2 * max(R, wmax - wmin) + 10)
    results = []
    cavity_rmax = 0.0
    t0 = time.time()
    for phi in angles:
        xd = math.cos(math.radians(phi)) * x + math.sin(math.radians(phi)) * y
        polys = []
        for k, sb in enumerate(fd.scene):
            tris, _ = section_polys(sb.solid, O, xd, e, Lbig)
            if tris:
                polys.append((k + 1, tris))
        lab = rasterize(polys, umin, wmin, px, (nu, nw))
        permm = np.isin(lab, [k + 1 for k in perm])
        solid = (lab > 0) & ~permm
        solid_d = ndimage.binary_dilation(solid)  # closes contacts/tangencies below one pixel
        air = ~solid_d
        band = None
        if moving_pairs:
            band = contact_band(lab, permm, moving_pairs)
            air |= band  # a running fit is a clearance, never a seal
        for sgn in (+1, -1):
            below = (sgn * ug >= A)[:, None] & np.ones((1, nw), bool)
            seeds = permm & below & air
            if not seeds.any():
                results.append({"phi": phi, "sgn": sgn, "status": "no seed"})
                continue
            region = air & below
            lb, n = ndimage.label(region)
            ids = np.unique(lb[seeds])
            ids = ids[ids > 0]
            Om = np.isin(lb, ids)
            border = np.zeros_like(Om)
            border[0, :] = border[-1, :] = True
            border[:, 0] = border[:, -1] = True
            leak = bool((Om & border).any())
            ii, jj = np.nonzero(Om)
            if len(ii):
                cavity_rmax = max(cavity_rmax, float(np.max(np.abs(ug[ii]))))
            res = {"phi": phi, "sgn": sgn, "status": "leak" if leak else "closed", "area_mm2": float(Om.sum() * px * px),
                   "lab": lab, "Om": Om, "solid": ~air, "permm": permm, "band": band}
            gdir0 = (phi + (0 if sgn > 0 else 180)) % 360
            if not leak and strict and (round(gdir0) % 90 == 0):
                res["joints"] = strict_joints(lab, permm, air, below, seeds, seal_labels, fd)
            if len(ii) and not leak:
                far = int(np.argmax(sgn * ug[ii]))
                res["rmax"] = float(abs(ug[ii[far]]))
                res["rmax_z"] = float(wmin + (jj[far] + 0.5) * px)
                # drain: gravity towards a port (section plane through the port axis)
                gdir = (phi + (0 if sgn > 0 else 180)) % 360
                wg = wmin + (np.arange(nw) + 0.5) * px
                down_ports = [p_ for p_ in ports if abs(((gdir - p_[0]) + 180) % 360 - 180) < 0.6]
                not_port = np.ones(nw, bool)
                for p_ in down_ports:
                    not_port &= np.abs(wg - p_[3]) > p_[4] + 0.3  # the port passages themselves drain
                for (th, r_in, pname, wq, rh) in down_ports:
                    if True:
                        ret = Om & ((sgn * ug)[:, None] > r_in + 0.3) & not_port[None, :]
                        res.setdefault("drain", []).append((pname, th, r_in, float(ret.sum() * px * px), res["rmax"], res["rmax_z"], id(res)))
                        res["ret"] = ret
            results.append(res)
    dt = time.time() - t0
    leaks = [r for r in results if r["status"] == "leak"]
    closed = [r for r in results if r["status"] == "closed"]
    noseed = [r for r in results if r["status"] == "no seed"]
    grav = lambda r: (r["phi"] + (0 if r["sgn"] > 0 else 180)) % 360
    F.ok("assembly", "oil flood fill", "%d gravity directions (%d section planes through the axis, %.2f mm pixels, %.0f s); oil level A = %g mm "
         "below the axis (datum assumed: horizontal axis, A measured from the axis down); bearings permeable, all other bodies solid, "
         "gaps < 1 pixel closed" % (len(results), len(angles), px, dt, A))
    if noseed and not leaks and not closed:
        F.add("info", "assembly", "oil check not evaluated: no bearing reaches below level A (no oil seed)", "-", "-")
        return
    worst = None
    if leaks:
        # path to the border for the first leaking direction(s)
        for r in leaks[:3]:
            path_info = leak_path(r, ug, wmin, px, fd)
            r["path"] = path_info
            if worst is None:
                worst = r
        gd = sorted({round(grav(r)) for r in leaks})
        pi = worst["path"]
        F.add("blocker", "assembly", "oil below level A reaches the outside in %d of %d gravity directions (θ_down = %s°); e.g. θ_down %d°: "
              "the path %s between %s and %s at r %.1f, z %.1f (local width ≈ %.2f mm; a running fit between parts that turn relative "
              "to each other counts as open)"
              % (len(leaks), len(results), ",".join(str(g) for g in gd[:24]), grav(worst), pi.get("where", ""), pi["a"], pi["b"],
                 pi["r"], pi["z"], pi["gap"]),
              "%d/%d directions leak" % (len(leaks), len(results)),
              "HOUSING_RULES §2: a plain gap below oil level A is a leak; seals/plugs only (seed 000 p.028)")
    else:
        F.ok("assembly", "oil containment", "closed below level A in all %d gravity directions with a seed" % len(closed))
    jrows = defaultdict(set)
    for r in results:
        for kind, pairs in r.get("joints", []):
            key = (kind, tuple(tuple(sorted((fd.short(a - 1), fd.short(b - 1)))) for a, b in pairs))
            jrows[key].add(round(grav(r)))
    for (kind, pairs), gd in sorted(jrows.items()):
        txt = " → ".join("[%s | %s]" % p for p in pairs)
        F.add("minor", "assembly (static joints)",
              "oil below level A reaches the outside along a path whose only barriers are metal-to-metal contacts / screw fits without an "
              "O-ring in the model (gravity θ %s°); joints crossed, inside → outside: %s. One of them needs sealant / sealing thread-locker "
              "(not visible in geometry — check the drawing)" % (",".join(str(g) for g in sorted(gd)), txt),
              "unsealed joint(s) on a leak path", "seed 000 p.028 (HOUSING_RULES §2): O-ring or sealant on flange faces and fits; "
              "sealing thread-locker on tapped through holes")
    if results and not jrows and strict:
        F.ok("assembly", "joints", "no metal-to-metal joint lies on an oil path to the outside (checked at 45° steps)")
    drains = [d for r in results for d in r.get("drain", [])]
    if ports:
        if drains:
            best = min(drains, key=lambda d: d[3])
            pname, th, r_in, area, rmax, rz, rid = best
            rr_ = next(r for r in results if id(r) == rid)
            render_oil(os.path.join(outdir, "assembly_oil_drain.png"), rr_, ug, wmin, px, A, fd, grav(rr_),
                       note="drain: port at θ %.0f° turned down; oil retained beyond r %.1f shown orange" % (th, r_in))
            if area > 0.5:
                from scipy import ndimage
                ret = rr_["ret"]
                width = float(2 * ndimage.distance_transform_edt(ret).max() * px)
                sev = "major" if width > 2.0 else "minor"
                F.add(sev, pname, "draining with the port at θ %.0f° turned down leaves oil in the cavity beyond its opening radius r %.1f: "
                      "the cavity reaches r %.1f (at z %.1f); retained section area ≈ %.1f mm² in that plane, widest pocket ≈ %.1f mm "
                      "(%s). Uncertain: bodies not in the review assembly (flexspline, wave-generator bearing) occupy part of the gear space, "
                      "so the retained amount is overestimated there" % (th, r_in, rmax, rz, area, width,
                                                                        "only thin gaps" if width <= 2.0 else "includes open cavity, not just gaps"),
                      "r_port %.1f < r_cavity %.1f" % (r_in, rmax), "HOUSING_RULES §3: draining needs a plug at the cavity's outer radius")
            else:
                F.ok(pname, "drain", "port at θ %.0f° (r %.1f) reaches the cavity's lowest point" % (th, r_in))
        else:
            F.add("info", "assembly", "drain check not evaluated (no closed section through a port axis)", "-", "-")
    # render the worst (or first) direction
    r = worst or (closed[0] if closed else None)
    if r is not None:
        render_oil(os.path.join(outdir, "assembly_oil_section.png"), r, ug, wmin, px, A, fd, grav(r))
    return cavity_rmax


def contact_band(lab, permm, pairs):
    """pixels (1–2 px wide) along contacts between the given label pairs, after growing labels by one pixel"""
    from scipy import ndimage
    L = lab.copy()
    L[permm] = 0
    d, (iy, ix) = ndimage.distance_transform_edt(L == 0, return_indices=True)
    L2 = np.where((L == 0) & (d <= 1.01), L[iy, ix], L)
    band = np.zeros(L.shape, bool)
    for sl_a, sl_b in (((slice(None), slice(None, -1)), (slice(None), slice(1, None))),
                       ((slice(None, -1), slice(None)), (slice(1, None), slice(None)))):
        A_, B_ = L2[sl_a], L2[sl_b]
        lo_, hi_ = np.minimum(A_, B_), np.maximum(A_, B_)
        m = np.zeros(A_.shape, bool)
        for a, b in pairs:
            m |= (lo_ == min(a, b)) & (hi_ == max(a, b))
        band[sl_a] |= m
        band[sl_b] |= m
    return band


def strict_joints(lab, permm, air, below, seeds, seal_labels, fd, max_iter=8):
    """flood again with every contact between two different non-seal bodies opened as a 1–2 px channel;
    returns the body-label pairs whose joint had to be closed (i.e. needs sealant) to stop the oil."""
    from scipy import ndimage
    L = lab.copy()
    L[permm] = 0
    # grow labels by one pixel into air so that near-contacts below one pixel count as contacts
    d, (iy, ix) = ndimage.distance_transform_edt(L == 0, return_indices=True)
    L2 = np.where((L == 0) & (d <= 1.01), L[iy, ix], L)
    jmask = np.zeros(L.shape, bool)
    pa = np.zeros(L.shape, np.int64)
    pb = np.zeros(L.shape, np.int64)
    for sl_a, sl_b in (((slice(None), slice(None, -1)), (slice(None), slice(1, None))),
                       ((slice(None, -1), slice(None)), (slice(1, None), slice(None)))):
        A_, B_ = L2[sl_a], L2[sl_b]
        m = (A_ != B_) & (A_ > 0) & (B_ > 0)
        m &= ~np.isin(A_, list(seal_labels)) & ~np.isin(B_, list(seal_labels))
        for sl in (sl_a, sl_b):
            jmask[sl] |= m
            pa[sl] = np.where(m, np.minimum(A_, B_), pa[sl])
            pb[sl] = np.where(m, np.maximum(A_, B_), pb[sl])
    border = np.zeros(L.shape, bool)
    border[0, :] = border[-1, :] = True
    border[:, 0] = border[:, -1] = True

    def leaks(sealed):
        open_j = jmask.copy()
        for (a, b) in sealed:
            open_j &= ~((pa == a) & (pb == b))
        region = (air | open_j) & below
        lb, n = ndimage.label(region)
        ids = np.unique(lb[seeds & region])
        ids = ids[ids > 0]
        Om = np.isin(lb, ids)
        return bool((Om & border).any()), Om, open_j

    sealed = set()
    groups = []
    for _ in range(max_iter):
        lk, Om, open_j = leaks(sealed)
        if not lk:
            break
        path = bfs_path(Om, seeds & Om)
        if path is None:
            break
        pi, pj = path
        chain = []
        for i_, j_ in zip(pi, pj):
            if open_j[i_, j_]:
                pr = (int(pa[i_, j_]), int(pb[i_, j_]))
                if not chain or chain[-1] != pr:
                    chain.append(pr)
        if not chain:
            break
        groups.append(("path", chain))
        sealed |= {chain[-1]}
    return groups


def bfs_path(Om, seeds):
    """shortest 4-connected pixel path inside Om from any seed to the image border"""
    from scipy import sparse
    from scipy.sparse.csgraph import breadth_first_order
    idx = -np.ones(Om.shape, dtype=np.int64)
    ii, jj = np.nonzero(Om)
    N = len(ii)
    if N == 0:
        return None
    idx[ii, jj] = np.arange(N)
    rows, cols = [], []
    for a, b in ((idx[:, :-1], idx[:, 1:]), (idx[:-1, :], idx[1:, :])):
        m = (a >= 0) & (b >= 0)
        rows.append(a[m])
        cols.append(b[m])
    s = idx[seeds]
    s = s[s >= 0]
    rows.append(np.full(len(s), N))
    cols.append(s)
    rows = np.concatenate(rows)
    cols = np.concatenate(cols)
    g = sparse.coo_matrix((np.ones(len(rows), np.int8), (rows, cols)), shape=(N + 1, N + 1)).tocsr()
    order, pred = breadth_first_order(g, N, directed=False, return_predecessors=True)
    bset = np.zeros(N + 1, bool)
    b_ = np.concatenate([idx[0, :], idx[-1, :], idx[:, 0], idx[:, -1]])
    bset[b_[b_ >= 0]] = True
    hit = order[bset[order]]
    if len(hit) == 0:
        return None
    cur = hit[0]
    path = []
    while cur != N and cur >= 0:
        path.append(cur)
        cur = pred[cur]
    path = path[::-1]
    return ii[path], jj[path]


def leak_path(r, ug, wmin, px, fd):
    from scipy import ndimage, sparse
    from scipy.sparse.csgraph import breadth_first_order
    Om = r["Om"]
    nu, nw = Om.shape
    idx = -np.ones(Om.shape, dtype=np.int64)
    ii, jj = np.nonzero(Om)
    N = len(ii)
    idx[ii, jj] = np.arange(N)
    rows, cols = [], []
    a = idx[:, :-1]
    b = idx[:, 1:]
    m = (a >= 0) & (b >= 0)
    rows.append(a[m])
    cols.append(b[m])
    a = idx[:-1, :]
    b = idx[1:, :]
    m = (a >= 0) & (b >= 0)
    rows.append(a[m])
    cols.append(b[m])
    seeds = idx[r["permm"] & Om]
    seeds = seeds[seeds >= 0]
    rows.append(np.full(len(seeds), N))
    cols.append(seeds)
    rows = np.concatenate(rows)
    cols = np.concatenate(cols)
    g = sparse.coo_matrix((np.ones(len(rows), np.int8), (rows, cols)), shape=(N + 1, N + 1)).tocsr()
    order, pred = breadth_first_order(g, N, directed=False, return_predecessors=True)
    border = set(np.concatenate([idx[0, :], idx[-1, :], idx[:, 0], idx[:, -1]]).tolist()) - {-1}
    target = next((o for o in order if o in border), None)
    info = {"gap": float("nan"), "a": "?", "b": "?", "r": float("nan"), "z": float("nan"), "pix": []}
    if target is None:
        return info
    path = []
    cur = target
    while cur != N and cur >= 0:
        path.append(cur)
        cur = pred[cur]
    path = path[::-1]
    pi, pj = ii[path], jj[path]
    solid = r["solid"]
    dist = ndimage.distance_transform_edt(~solid)
    body = (r["lab"] > 0) & ~r["permm"]
    bd = ndimage.distance_transform_edt(~body)

    def two_bodies(ci, cj, win=25):
        found = []
        for rad in range(1, win + 1):
            sl = r["lab"][max(ci - rad, 0):ci + rad + 1, max(cj - rad, 0):cj + rad + 1]
            bm = body[max(ci - rad, 0):ci + rad + 1, max(cj - rad, 0):cj + rad + 1]
            for l in np.unique(sl[bm]):
                if l not in found:
                    found.append(int(l))
            if len(found) >= 2:
                break
        return (found + [0, 0])[:2]
    band = r.get("band")
    kcross = None
    if band is not None:
        inb = np.nonzero(band[pi, pj])[0]
        if len(inb):
            kcross = int(inb[0])
    near_body = np.nonzero(bd[pi, pj] <= 2.0)[0]
    kexit = int(near_body[-1]) if len(near_body) else len(pi) - 1
    kk = kcross if kcross is not None else kexit
    ci, cj = pi[kk], pj[kk]
    la, lb_ = two_bodies(ci, cj)
    dd = dist[pi, pj]
    kmin = kk
    name = lambda l: fd.short(l - 1) if l > 0 else "?"
    info.update({"gap": float(2 * dd[kmin] * px), "a": name(la), "b": name(lb_), "r": float(abs(ug[ci])),
                 "z": float(wmin + (cj + 0.5) * px), "pix": (pi, pj),
                 "where": "crosses a running fit" if kcross is not None else "leaves the assembly"})
    return info


def render_oil(path_png, r, ug, wmin, px, A, fd, gdir, note=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    lab, Om = r["lab"], r["Om"]
    nu, nw = lab.shape
    img = np.ones((nu, nw, 3))
    img[lab > 0] = (0.62, 0.71, 0.80)
    img[r["permm"]] = (0.85, 0.75, 0.55)
    img[Om] = (0.45, 0.65, 1.0)
    if note and r.get("ret") is not None:
        img[r["ret"]] = (1.0, 0.55, 0.0)
    if r.get("path") and len(r["path"]["pix"]):
        pi, pj = r["path"]["pix"]
        img[pi, pj] = (1, 0, 0)
    ext = [wmin, wmin + nw * px, ug[0] - px / 2, ug[-1] + px / 2]
    fig, ax = plt.subplots(figsize=(13, 9))
    ax.imshow(img, origin="lower", extent=ext, interpolation="nearest")
    if r["sgn"] > 0:
        ax.invert_yaxis()  # gravity points down on the page
    ax.axhline(r["sgn"] * A, color="b", ls="--", lw=0.8)
    ax.axhline(0, color="r", ls="-.", lw=0.5)
    ax.set_title("%s: section at %.0f°, gravity towards θ=%d° (%s u); oil level A=%g (dashed); oil region blue; %s"
                 % (fd.model, r["phi"], gdir, "+" if r["sgn"] > 0 else "−", A,
                    "LEAK path red (gap %.2f mm between %s and %s)" % (r["path"]["gap"], r["path"]["a"], r["path"]["b"]) if r.get("path") else (note or "closed")),
                 fontsize=8)
    ax.set_xlabel("axial z [mm]")
    ax.set_ylabel("u in section plane [mm] (gravity %s)" % ("+u" if r["sgn"] > 0 else "−u"))
    fig.tight_layout()
    fig.savefig(path_png, dpi=170)
    plt.close(fig)


# ----------------------------------------------------------------------------------------------
# driver
# ----------------------------------------------------------------------------------------------
def part_section_png(fd, prt, holes, outdir):
    b = prt["ab"]
    O, e = b.axis
    x, y = perp_basis(e)
    phi = 0.0
    ax_holes = [h for h in holes if h["kind_dir"] in ("axial", "radial")]
    if ax_holes:
        h = ax_holes[0]
        r_, z_, th = b.rz(np.array([h["center"]]))
        phi = float(np.degrees(th[0])) if r_[0] > 1e-3 else 0.0
        if h["kind_dir"] == "radial":
            phi = h["theta"]
    xd = math.cos(math.radians(phi)) * x + math.sin(math.radians(phi)) * y
    L = float(2 * np.linalg.norm(b.bb[1] - b.bb[0]) + 10)
    tris, lines = section_polys(b.solid, O, xd, e, L)
    fn = os.path.join(outdir, "%s.png" % prt["name"])
    render_part_section(fn, "%s (%s): axial section through the part's main axis at θ = %.0f° (plane also shows θ+180°)"
                        % (prt["name"], fd.model, phi), tris, lines)
    return fn


def print_table(fd, out=sys.stdout, show_ok=False):
    rows = sorted(fd.F.rows, key=lambda r: (SEV_ORDER[r["severity"]], r["part"]))
    w = out.write
    w("\n" + "=" * 120 + "\n")
    w("%s  (%s, family %s, material %s, lubricant %s%s)\n" % (fd.model, fd.path, fd.family, fd.material, fd.lubrication,
                                                            ", oil level A %g mm" % fd.A if fd.A is not None else ""))
    cnt = defaultdict(int)
    for r in rows:
        cnt[r["severity"]] += 1
    w("findings: %d blocker, %d major, %d minor, %d info; %d further measurements within the rules (--show-ok lists them)\n"
      % (cnt["blocker"], cnt["major"], cnt["minor"], cnt["info"], len(fd.F.measured)))
    w("-" * 120 + "\n")
    for r in rows:
        w("[%-7s] %-28s | %s\n          measured: %s | rule: %s\n" % (r["severity"], r["part"][:28], r["finding"], r["measured"], r["rule"]))
    if show_ok:
        w("-" * 120 + "\nmeasured and within the rules:\n")
        for m in fd.F.measured:
            w("  ok  %-28s | %s: %s\n" % (m["part"][:28], m["check"], m["measured"]))


def run_folder(path, cat, args):
    t0 = time.time()
    fd = Folder(path, cat, log=print)
    fd.load()
    outdir = os.path.join(path, "probe_sections")
    os.makedirs(outdir, exist_ok=True)
    timing = {}

    def guarded(name, fn, *a, **k):
        """a failing check is reported, never silently skipped, and does not stop the others"""
        t = time.time()
        try:
            return fn(*a, **k)
        except Exception as ex:
            import traceback
            fd.F.add("info", "probe", "check '%s' could not run: %s: %s (NOT MEASURED)" % (name, type(ex).__name__, ex),
                     traceback.format_exc(limit=2).strip().splitlines()[-1][:160], "-")
            return None
        finally:
            timing[name] = timing.get(name, 0.0) + time.time() - t

    guarded("validity", check_validity, fd)
    fd.relmove = set()
    guarded("mass", check_mass, fd)
    guarded("interference", check_interference, fd)
    stacks = (guarded("bearings", check_bearings, fd) or {}) if fd.review else {}
    guarded("relative motion", relative_motion, fd, stacks)
    pngs = []
    for prt in fd.parts:
        if prt["ab"] is None:
            continue
        b = prt["ab"]
        holes = guarded("holes", find_holes, b, cat) or []
        prt["holes"] = holes
        guarded("holes", check_holes, fd, prt, holes)
        diag = float(np.linalg.norm(b.bb[1] - b.bb[0]))
        h_s = max(1.0, diag / 80.0) if args.quick else max(0.5, diag / 120.0)
        eb = guarded("edges", check_edges, fd, prt) or ([], [])
        sgc = guarded("seats", check_seats, fd, prt, stacks)
        sg = sgc[0] if sgc else {"seats": [], "grooves": []}
        guarded("grooves", check_grooves, fd, prt, sg, holes)
        ring_faces = {}
        for g in sg["grooves"]:
            if g.get("match") and g["match"].startswith("DIN"):
                m = classify_groove(g, cat)[0][1]
                for fi in [g["face"]] + g.get("walls", []):
                    ring_faces[fi] = m["n"]
        guarded("walls", check_walls, fd, prt, holes, h_s, breaks=frozenset(x["face"] for x in eb[1]), ring_faces=ring_faces)
        guarded("lead-ins", check_mating_leadins, fd, prt)
        guarded("ports", check_port_access, fd, prt, holes)
        p = guarded("section png", part_section_png, fd, prt, holes, outdir)
        if p:
            pngs.append(p)
    guarded("seals", check_seals_orings, fd)
    guarded("screws", check_screws, fd)
    if fd.family in ("GH", "2A-GR"):
        guarded("static joints", check_static_joints, fd)
    if fd.family == "FD-0":
        fd.F.add("info", "assembly", "the FD-0 unit is one outline solid: whether the drive-flange faces touch the unit's internal 6xxx inner "
                 "rings (HOUSING_RULES §1 abutment remark) cannot be measured", "NOT MEASURED", "HOUSING_RULES §1")
    if fd.family == "FD-2" and fd.lubrication == "oil":
        if args.no_oil:
            fd.F.add("info", "assembly", "oil flood fill skipped (--no-oil)", "-", "-")
        else:
            ports = []
            O_, e_ = fd.main_axis
            x_, y_ = perp_basis(e_)
            ang = []
            for prt in fd.parts:
                for h in prt.get("holes", []):
                    q = h["center"] - O_
                    wq = float(np.dot(q, e_))
                    rv = q - wq * e_
                    thm = math.degrees(math.atan2(np.dot(rv, y_), np.dot(rv, x_)))
                    if h["kind_dir"] == "radial":
                        thm = math.degrees(math.atan2(np.dot(h["a"], y_), np.dot(h["a"], x_)))
                        ops = opening_positions(prt["ab"], h)
                        if ops:
                            sgn = max(ops, key=lambda s: ops[s][0])
                            if sgn < 0:
                                thm += 180
                    ang.append(thm)
                    if h["kind"] == "port" and "r_inner" in h:
                        ports.append((thm % 360, h["r_inner"], prt["name"], wq, max(s["r"] for s in h["segs"])))
            guarded("oil", oil_check, fd, outdir, extra_angles=ang, ports=ports)
    elif fd.lubrication == "oil":
        fd.F.add("info", "assembly", "oil check not applicable: the generated parts hold no oil cavity of their own (%s)" % fd.family, "-", "-")
    else:
        fd.F.add("info", "assembly", "oil check not applicable: lubricant %s" % fd.lubrication, "-", "-")
    fd.timing = timing
    fd.elapsed = time.time() - t0
    fd.pngs = pngs
    with open(os.path.join(outdir, "probe_findings.json"), "w", encoding="utf-8") as f:
        json.dump({"model": fd.model, "family": fd.family, "findings": fd.F.rows, "measured_ok": fd.F.measured,
                   "timing_s": timing}, f, indent=1, default=str)
    return fd


def expand(paths):
    out = []
    for p in paths:
        if os.path.exists(os.path.join(p, "assembly.step")) or glob.glob(os.path.join(p, "*.step")):
            out.append(p)
        else:
            for q in sorted(glob.glob(os.path.join(p, "*"))):
                if os.path.isdir(q) and glob.glob(os.path.join(q, "*.step")):
                    out.append(q)
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdirs", nargs="+")
    ap.add_argument("--no-oil", action="store_true", help="skip the oil flood fill")
    ap.add_argument("--catalog", default=CATALOG_DEFAULT)
    ap.add_argument("--quick", action="store_true", help="coarser wall-thickness sampling")
    ap.add_argument("--show-ok", action="store_true", help="also list what was measured and passed")
    ap.add_argument("--json", help="write all findings to this file")
    args = ap.parse_args(argv)
    cat = Catalog(args.catalog)
    folders = expand(args.outdirs)
    if not folders:
        print("no hdcad output folders found in", args.outdirs, file=sys.stderr)
        return 2
    print("Severity: blocker = cannot be built/assembled or will fail (leak, interference, unstopped bearing, wall < 1 mm); "
          "major = violates a HOUSING_RULES number or standard; minor = deviation from good practice / local; info = context.")
    allf = []
    worst = 3
    for p in folders:
        fd = run_folder(p, cat, args)
        print_table(fd, show_ok=args.show_ok)
        print("time %.0f s (%s); sections: %s" % (fd.elapsed, ", ".join("%s %.0f" % kv for kv in fd.timing.items()),
                                                os.path.join(p, "probe_sections")))
        allf.append({"model": fd.model, "folder": p, "findings": fd.F.rows})
        for r in fd.F.rows:
            worst = min(worst, SEV_ORDER[r["severity"]])
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(allf, f, indent=1, default=str)
    return 1 if worst <= 1 else 0


if __name__ == "__main__":
    sys.exit(main())
