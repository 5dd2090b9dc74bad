# Writes a .vti's grid as N slabs along z (raw .vti pieces) and a .pvti naming them:
#   python3 pieces.py GRID.vti STEM N  ->  STEM.pvti, STEM_0.vti ... (Debian's python3-vtk9)
import vtk, sys
from vtk.util import numpy_support as ns
src = sys.argv[1]; stem = sys.argv[2]; n = int(sys.argv[3])
r = vtk.vtkXMLImageDataReader(); r.SetFileName(src); r.Update()
im = r.GetOutput()
e = im.GetExtent()
v = ns.vtk_to_numpy(im.GetPointData().GetArray('velocity'))
nx, ny, nz = e[1]-e[0]+1, e[3]-e[2]+1, e[5]-e[4]+1
v = v.reshape(nz, ny, nx, 3)
pieces = []
for p in range(n):
    z0 = p*(nz-1)//n; z1 = (p+1)*(nz-1)//n
    pi = vtk.vtkImageData(); pi.SetExtent(e[0], e[1], e[2], e[3], z0, z1)
    pi.SetOrigin(im.GetOrigin()); pi.SetSpacing(im.GetSpacing())
    a = ns.numpy_to_vtk(v[z0:z1+1].reshape(-1,3).copy(), deep=1); a.SetName('velocity')
    pi.GetPointData().AddArray(a)
    w = vtk.vtkXMLImageDataWriter(); w.SetInputData(pi); f = '%s_%d.vti' % (stem, p); w.SetFileName(f)
    w.SetDataModeToAppended(); w.EncodeAppendedDataOff(); w.SetCompressorTypeToNone(); w.Write()
    pieces.append(((e[0], e[1], e[2], e[3], z0, z1), f))
o = im.GetOrigin(); s = im.GetSpacing()
with open(stem + '.pvti', 'w') as out:
    out.write('<VTKFile type="PImageData" version="0.1" byte_order="LittleEndian">\n')
    out.write('<PImageData WholeExtent="%d %d %d %d %d %d" GhostLevel="0" Origin="%r %r %r" Spacing="%r %r %r">\n' % (tuple(e) + tuple(o) + tuple(s)))
    out.write('<PPointData Vectors="velocity"><PDataArray type="Float32" Name="velocity" NumberOfComponents="3"/></PPointData>\n')
    for ext, f in pieces:
        out.write('<Piece Extent="%d %d %d %d %d %d" Source="%s"/>\n' % (tuple(ext) + (f.split('/')[-1],)))
    out.write('</PImageData>\n</VTKFile>\n')
