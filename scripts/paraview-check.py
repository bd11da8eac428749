#!/usr/bin/python3
"""Opens a .vtu that loom wrote in ParaView (Debian's python3-paraview) and
checks that ParaView reads what loom's JSON report says: as many cells, all
hexahedra, the cell fields of docs/formats.md with the report's counts, and the
same minimum scaled Jacobian; and ParaView's own Mesh Quality (Verdict, which
tests each hex's centre as well as its corners) gives the report's
verdict_min_scaled_jacobian and verdict_below_zero. Usage: scripts/paraview-check.py MESH.vtu REPORT.json
"""
import json, sys

from paraview import servermanager
from paraview.simple import MeshQuality, XMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy

VTK_HEXAHEDRON = 12
FIELDS = ['source', 'scaled_jacobian', 'sheet_i', 'sheet_j', 'sheet_k', 'inversion_cause']
SOURCES = ['woven', 'searched', 'database', 'filled', 'pillow']  # docs/formats.md
CAUSES = {1: 'locked_corner', 2: 'crowded_edge', 3: 'unexplained'}


def fail(what):
    sys.exit('paraview-check: %s: %s' % (sys.argv[1], what))


def main(mesh, report_path):
    report = json.load(open(report_path))
    reader = XMLUnstructuredGridReader(FileName=[mesh])
    reader.UpdatePipeline()
    grid = servermanager.Fetch(reader)
    cells = grid.GetNumberOfCells()
    if cells != report['hexes']: fail('ParaView reads %d cells, the report says %d hexes' % (cells, report['hexes']))
    types = {grid.GetCellType(c) for c in range(cells)}
    if types != {VTK_HEXAHEDRON}: fail('cell types %s, not only hexahedra' % sorted(types))
    data = grid.GetCellData()
    arrays = {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)) for i in range(data.GetNumberOfArrays())}
    missing = [f for f in FIELDS if f not in arrays]
    if missing: fail('no cell field %s' % ', '.join(missing))
    for k, name in enumerate(SOURCES):
        n = int((arrays['source'] == k).sum())
        if n != report['hex_sources'][name]: fail('%d hexes from %s, the report says %d' % (n, name, report['hex_sources'][name]))
    for k, name in CAUSES.items():
        n = int((arrays['inversion_cause'] == k).sum())
        if n != report['inversion_causes'][name]: fail('%d hexes %s, the report says %d' % (n, name, report['inversion_causes'][name]))
    low = float(arrays['scaled_jacobian'].min())
    if abs(low - report['min_scaled_jacobian']) > 1e-6:
        fail('minimum scaled Jacobian %.6f, the report says %.6f' % (low, report['min_scaled_jacobian']))
    quality = MeshQuality(Input=reader, HexQualityMeasure='Scaled Jacobian')
    quality.UpdatePipeline()
    verdict = vtk_to_numpy(servermanager.Fetch(quality).GetCellData().GetArray('Quality'))
    if abs(float(verdict.min()) - report['verdict_min_scaled_jacobian']) > 1e-6:
        fail('Verdict minimum %.6f, the report says %.6f' % (float(verdict.min()), report['verdict_min_scaled_jacobian']))
    if int((verdict <= 0).sum()) != report['verdict_below_zero']:
        fail('%d hexes <= 0 by Verdict, the report says %d' % (int((verdict <= 0).sum()), report['verdict_below_zero']))
    print('%s: ParaView reads %d hexahedra with fields %s; loom min scaled Jacobian %.3f, '
          'ParaView (Verdict) %.3f; hexes <= 0: loom %d, Verdict %d'
          % (mesh, cells, ', '.join(FIELDS), low, float(verdict.min()), int((arrays['scaled_jacobian'] <= 0).sum()),
             int((verdict <= 0).sum())))


if __name__ == '__main__':
    if len(sys.argv) != 3: sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
