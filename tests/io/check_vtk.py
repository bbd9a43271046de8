#!/usr/bin/python3
"""Checks dilatant's ParaView output with VTK's own XML reader.

Usage: /usr/bin/python3 check_vtk.py SPEC.json

SPEC.json (written by tests/io/vtk_writer_test.cpp):
  {"polydata": [{"file": "/abs/x.vtp", "points": N, "verts": N, "lines": N,
                 "points_xyz": [x0, y0, z0, x1, ...],          (optional)
                 "line_lengths": [l0, l1, ...],                (optional)
                 "point_data": {NAME: {"type": "Float64", "components": 3,
                                       "values": [flattened tuples]}},  (values optional)
                 "cell_data": {...same...}}],
   "pvd": [{"file": "/abs/x.pvd",
            "datasets": [{"timestep": t, "group": "", "part": 0, "file": "rel.vtp"}]}]}

The arrays of each file must be exactly those listed. Every file a .pvd lists must
load without a VTK error or warning and be one of the "polydata" files.
Exit 0 when everything matches; otherwise print each mismatch and exit 1.
Exit 3 if VTK cannot be imported.
"""
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

try:
    from vtkmodules import vtkCommonCore as vtk_core
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
except ImportError as e:  # pragma: no cover - environment problem
    print(f"check_vtk.py: {sys.executable} cannot import VTK ({e}); install python3-vtk9")
    sys.exit(3)

# XML type name -> accepted (VTK type codes, size in bytes).
TYPES = {
    "Float64": ({vtk_core.VTK_DOUBLE}, 8),
    "Float32": ({vtk_core.VTK_FLOAT}, 4),
    "Int64": ({vtk_core.VTK_LONG, vtk_core.VTK_LONG_LONG, vtk_core.VTK_ID_TYPE}, 8),
    "Int32": ({vtk_core.VTK_INT}, 4),
    "UInt8": ({vtk_core.VTK_UNSIGNED_CHAR}, 1),
}

REL_TOL = 1e-12
ABS_TOL = 1e-14

errors = []
log = vtk_core.vtkStringOutputWindow()
vtk_core.vtkOutputWindow.SetInstance(log)


def fail(msg):
    errors.append(msg)


def close(a, b):
    if isinstance(a, int) and isinstance(b, int):
        return a == b
    return math.isclose(a, b, rel_tol=REL_TOL, abs_tol=ABS_TOL)


def read_polydata(path):
    """The reader's output, or None (with the error recorded)."""
    if not os.path.isfile(path):
        fail(f"{path}: missing")
        return None
    before = len(log.GetOutput())
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    messages = log.GetOutput()[before:].strip()
    if messages:
        fail(f"{path}: VTK reported:\n{messages}")
        return None
    return reader.GetOutput()


def check_values(where, got, want):
    if len(got) != len(want):
        fail(f"{where}: {len(got)} values, expected {len(want)}")
        return
    for k, (g, w) in enumerate(zip(got, want)):
        if not close(g, w):
            fail(f"{where}[{k}] = {g!r}, expected {w!r}")


def check_arrays(path, kind, data, tuples, spec):
    names = sorted(data.GetArrayName(k) for k in range(data.GetNumberOfArrays()))
    if names != sorted(spec):
        fail(f"{path}: {kind} arrays {names}, expected {sorted(spec)}")
    for name, want in spec.items():
        array = data.GetArray(name)
        where = f"{path}: {kind} '{name}'"
        if array is None:
            continue  # already reported
        codes, size = TYPES[want["type"]]
        if array.GetDataType() not in codes or array.GetDataTypeSize() != size:
            fail(f"{where}: VTK type {array.GetDataTypeAsString()}, expected {want['type']}")
        if array.GetNumberOfComponents() != want["components"]:
            fail(f"{where}: {array.GetNumberOfComponents()} components, "
                 f"expected {want['components']}")
        if array.GetNumberOfTuples() != tuples:
            fail(f"{where}: {array.GetNumberOfTuples()} tuples, expected {tuples}")
        if "values" in want:
            got = [array.GetValue(k) for k in range(array.GetNumberOfValues())]
            check_values(where, got, want["values"])


def check_polydata(spec):
    path = spec["file"]
    out = read_polydata(path)
    if out is None:
        return
    counts = {
        "points": out.GetNumberOfPoints(),
        "verts": out.GetNumberOfVerts(),
        "lines": out.GetNumberOfLines(),
        "polys": out.GetNumberOfPolys(),
        "strips": out.GetNumberOfStrips(),
    }
    for key, got in counts.items():
        want = spec.get(key, 0)
        if got != want:
            fail(f"{path}: {got} {key}, expected {want}")

    if "points_xyz" in spec:
        got = []
        for k in range(out.GetNumberOfPoints()):
            got.extend(out.GetPoint(k))
        check_values(f"{path}: points", got, spec["points_xyz"])

    if "line_lengths" in spec:
        lines = out.GetLines()
        got = []
        for c in range(lines.GetNumberOfCells()):
            id_list = vtk_core.vtkIdList()
            lines.GetCellAtId(c, id_list)
            ids = [id_list.GetId(p) for p in range(id_list.GetNumberOfIds())]
            if len(ids) != 2:
                fail(f"{path}: line {c} has {len(ids)} points")
                continue
            a, b = out.GetPoint(ids[0]), out.GetPoint(ids[1])
            got.append(math.dist(a, b))
        check_values(f"{path}: line lengths", got, spec["line_lengths"])

    check_arrays(path, "point data", out.GetPointData(), out.GetNumberOfPoints(),
                 spec.get("point_data", {}))
    check_arrays(path, "cell data", out.GetCellData(), out.GetNumberOfCells(),
                 spec.get("cell_data", {}))


def check_pvd(spec, known_files):
    path = spec["file"]
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as e:
        fail(f"{path}: cannot parse: {e}")
        return
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        fail(f"{path}: root <{root.tag} type={root.get('type')!r}>, "
             "expected <VTKFile type='Collection'>")
    collections = root.findall("Collection")
    if len(collections) != 1:
        fail(f"{path}: {len(collections)} <Collection> elements, expected 1")
        return
    datasets = collections[0].findall("DataSet")
    want = spec["datasets"]
    if len(datasets) != len(want):
        fail(f"{path}: {len(datasets)} data sets, expected {len(want)}")
    for k, (ds, w) in enumerate(zip(datasets, want)):
        where = f"{path}: DataSet {k}"
        try:
            timestep = float(ds.get("timestep"))
            part = int(ds.get("part"))
        except (TypeError, ValueError):
            fail(f"{where}: bad timestep/part {ds.attrib}")
            continue
        if not close(timestep, w["timestep"]):
            fail(f"{where}: timestep {timestep}, expected {w['timestep']}")
        if part != w["part"]:
            fail(f"{where}: part {part}, expected {w['part']}")
        if ds.get("group") != w["group"]:
            fail(f"{where}: group {ds.get('group')!r}, expected {w['group']!r}")
        if ds.get("file") != w["file"]:
            fail(f"{where}: file {ds.get('file')!r}, expected {w['file']!r}")
            continue
        listed = os.path.join(os.path.dirname(path), ds.get("file"))
        if os.path.realpath(listed) not in known_files:
            fail(f"{where}: {listed} is not one of the checked files")
        elif read_polydata(listed) is None:
            fail(f"{where}: {listed} does not load")


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    with open(sys.argv[1], encoding="utf-8") as f:
        spec = json.load(f)
    for pd in spec.get("polydata", []):
        check_polydata(pd)
    known = {os.path.realpath(pd["file"]) for pd in spec.get("polydata", [])}
    for pvd in spec.get("pvd", []):
        check_pvd(pvd, known)
    if errors:
        for e in errors:
            print("check_vtk.py: " + e)
        return 1
    print(f"check_vtk.py: {len(spec.get('polydata', []))} .vtp and "
          f"{len(spec.get('pvd', []))} .pvd files OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
