#!/usr/bin/env python3
"""Check a shcontact result file and its XDMF sidecar (issue 15).

    python3 scripts/check_xdmf.py OUT.xmf [--attributes]
    pvbatch scripts/check_xdmf.py --paraview /abs/path/OUT.xmf

Without --paraview (needs h5py and numpy): the sidecar is well-formed XML; every DataItem it
references exists in the HDF5 file with the declared dimensions and number type (Float 8/4,
Char 1, Int 4); each grid's geometry and attributes have the shape of its topology. With
--attributes, also: every dataset of the HDF5 file has `units` and `long_name`, every element
field (x, xy, pn, px, py, slip, state) has dimension scales attached (its strip dimension to
the strip centres `y`), every dimension of every dataset has a scale, and the root carries
the provenance attributes.

With --paraview, run by ParaView's pvbatch (or pvpython): the sidecar is opened with
ParaView's default XDMF reader and the point count and field names are printed; give an
absolute path (the reader resolves the HDF5 file against it).

Exit status 0 when everything holds, 1 with one line per problem otherwise.
"""
import os
import sys
import xml.etree.ElementTree as ET

FIELDS = ("x", "xy", "pn", "px", "py", "slip", "state")
PROVENANCE = ("software", "version", "git_revision", "compiler", "compiler_options", "host",
              "threads", "date", "command_line")
#: XDMF number type and precision of a numpy dtype.
KIND = {"f": "Float", "i": "Int", "u": "UInt"}


def xdmf_type(dtype):
    """(NumberType, Precision) XDMF uses for a numpy dtype."""
    if dtype.kind in "iu" and dtype.itemsize == 1:
        return ("Char" if dtype.kind == "i" else "UChar", 1)
    return (KIND.get(dtype.kind, "?"), dtype.itemsize)


def check_sidecar(xmf, problems):
    """Every DataItem of the sidecar against the HDF5 file it names."""
    import h5py
    tree = ET.parse(xmf)
    folder = os.path.dirname(os.path.abspath(xmf))
    files = {}
    n_grids = 0
    for grid in tree.iter("Grid"):
        if grid.get("GridType", "Uniform") != "Uniform":
            continue
        n_grids += 1
        name = grid.get("Name")
        topo = grid.find("Topology")
        if topo is None or topo.get("TopologyType") != "2DSMesh":
            problems.append(f"{name}: no 2DSMesh topology")
            continue
        mesh = tuple(int(n) for n in topo.get("Dimensions").split())
        for item in grid.iter("DataItem"):
            dims = tuple(int(n) for n in item.get("Dimensions").split())
            h5name, _, path = item.text.strip().partition(":")
            if h5name not in files:
                files[h5name] = h5py.File(os.path.join(folder, h5name), "r")
            f = files[h5name]
            if path not in f:
                problems.append(f"{name}: {h5name}:{path} does not exist")
                continue
            data = f[path]
            if data.shape != dims:
                problems.append(f"{name}: {path} has shape {data.shape}, the sidecar says {dims}")
            declared = (item.get("NumberType", "Float"), int(item.get("Precision", "4")))
            if xdmf_type(data.dtype) != declared:
                problems.append(f"{name}: {path} is {data.dtype}, the sidecar says {declared}")
            if dims[:2] != mesh:
                problems.append(f"{name}: {path} does not span the mesh {mesh}")
    if n_grids == 0:
        problems.append(f"{xmf}: no grid")
    for f in files.values():
        f.close()
    return n_grids


def check_attributes(h5, problems):
    """units and long_name everywhere, scales on the element fields, provenance on the root."""
    import h5py
    with h5py.File(h5, "r") as f:
        for key in PROVENANCE:
            if key not in f.attrs:
                problems.append(f"{h5}: root attribute {key} missing")

        def visit(name, obj):
            if not isinstance(obj, h5py.Dataset):
                return
            for key in ("units", "long_name"):
                if key not in obj.attrs:
                    problems.append(f"{h5}: /{name} has no {key}")
            base = name.rsplit("/", 1)[-1]
            if "/tangential/" in name and base in FIELDS:
                strip_dim = obj.dims[0]
                if not [s for s in strip_dim.values() if s.name.endswith("/tangential/y")]:
                    problems.append(f"{h5}: /{name}: the strip dimension has no scale y")
            if name.startswith("summary/") and base != "case":
                if not [s for s in obj.dims[0].values() if s.name == "/summary/case"]:
                    problems.append(f"{h5}: /{name}: no dimension scale summary/case")
            # Every dimension of every table has a scale (netCDF readers such as xarray refuse
            # a variable mixing labelled and unlabelled dimensions).
            is_scale = obj.attrs.get("CLASS", b"") in (b"DIMENSION_SCALE", "DIMENSION_SCALE")
            if not is_scale:
                for k, dim in enumerate(obj.dims):
                    if len(dim) == 0:
                        problems.append(f"{h5}: /{name}: dimension {k} has no scale")
        f.visititems(visit)


def check_paraview(xmf):
    """Open the sidecar with ParaView's reader (run under pvbatch/pvpython)."""
    from paraview.simple import OpenDataFile
    reader = OpenDataFile(os.path.abspath(xmf))
    if reader is None:
        print(f"{xmf}: ParaView has no reader for it")
        return 1
    reader.UpdatePipeline()
    info = reader.GetDataInformation()
    names = list(reader.PointData.keys())
    times = reader.TimestepValues
    times = [times] if isinstance(times, (int, float)) else list(times)
    print(f"reader {type(reader).__name__}, {info.GetNumberOfPoints()} points, "
          f"times {times}, fields {' '.join(names)}")
    return 0 if info.GetNumberOfPoints() > 0 and names else 1


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    if len(args) != 1:
        print(__doc__)
        return 2
    xmf = args[0]
    if "--paraview" in argv:
        return check_paraview(xmf)
    problems = []
    n = check_sidecar(xmf, problems)
    if "--attributes" in argv:
        h5 = ET.parse(xmf).getroot().find(".//DataItem").text.strip().partition(":")[0]
        check_attributes(os.path.join(os.path.dirname(os.path.abspath(xmf)), h5), problems)
    for p in problems:
        print(p)
    if not problems:
        print(f"{xmf}: {n} grids, every dataset found with its shape and type")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
