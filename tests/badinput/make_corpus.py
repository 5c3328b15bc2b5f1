#!/usr/bin/env python3
"""Writes a corpus of malformed mesh files, one per class of defect, into
DIR (generated, never checked in). Every file must make every command exit
with status 2 and a one-line error naming the problem.

    python3 tests/badinput/make_corpus.py DIR
"""
import os
import struct
import sys

out = sys.argv[1]
os.makedirs(out, exist_ok=True)


def write(name, data):
    mode = 'wb' if isinstance(data, bytes) else 'w'
    with open(os.path.join(out, name), mode) as f:
        f.write(data)


TRI = 'v 0 0 0\nv 1 0 0\nv 0 1 0\n'
# OBJ: indices out of range, zero, negative past the start, a byte-order
# mark, non-finite coordinates, degenerate faces.
write('obj_index_too_large.obj', TRI + 'f 1 2 7\n')
write('obj_index_zero.obj', TRI + 'f 0 1 2\n')
write('obj_negative_before_start.obj', TRI + 'f -1 -2 -9\n')
write('obj_huge_index.obj', TRI + 'f 1 2 4000000000\n')
write('obj_bom.obj', '\ufeff' + TRI + 'f 1 2 3\n')
write('obj_utf16.obj', (TRI + 'f 1 2 3\n').encode('utf-16'))  # with its byte-order mark
write('obj_utf16_be_no_mark.obj', (TRI + 'f 1 2 3\n').encode('utf-16-be'))
write('obj_nan.obj', 'v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n')
write('obj_inf.obj', 'v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n')
write('obj_empty_face.obj', TRI + 'f\n')
write('obj_two_vertex_face.obj', TRI + 'f 1 2\n')
write('obj_no_faces.obj', TRI)
write('obj_garbage_index.obj', TRI + 'f 1 2 x\n')
# Found by fuzz/MeshReaderFuzzer (VTK's OBJ reader crashed on both).
write('obj_vertex_five_numbers.obj', TRI + 'v 1 1 0 0 0.5\nf 1 2 3\n')
write('obj_colour_on_some_vertices.obj', 'v 0 0 0\nv 1 0 0 1 0 0\nv 0 1 0\nf 1 2 3\n')
# OFF (our own parser).
write('off_index_too_large.off', 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n')
write('off_negative_index.off', 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n')
write('off_huge_counts.off', 'OFF\n2000000000 2000000000 0\n0 0 0\n')
write('off_truncated.off', 'OFF\n3 1 0\n0 0 0\n1 0 0\n')
write('off_all_degenerate.off', 'OFF\n3 2 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n3 0 0 1\n')
write('off_huge_face_size.off', 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n')
# PLY: indices, counts, truncation, missing coordinates.
PLY_HEAD = 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n'
write('ply_index_too_large.ply', PLY_HEAD + '0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n')
write('ply_negative_index.ply', PLY_HEAD + '0 0 0\n1 0 0\n0 1 0\n3 0 -5 2\n')
write('ply_truncated_data.ply', PLY_HEAD + '0 0 0\n1 0\n')
write('ply_truncated_header.ply', 'ply\nformat ascii 1.0\nelement vertex 3\nprop')
write('ply_no_xyz.ply', PLY_HEAD.replace('property float x\nproperty float y\nproperty float z\n', 'property float u\n') + '0\n1\n2\n3 0 1 2\n')
write('ply_negative_count.ply', PLY_HEAD.replace('element vertex 3', 'element vertex -3') + '3 0 1 2\n')
write('ply_nan.ply', PLY_HEAD + '0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n')
# Found by fuzz/MeshReaderFuzzer (crash, assertion and double free in
# VTK's PLY reader).
write('ply_unknown_header_line.ply', PLY_HEAD.replace('property list', 'rop0perty list') + '0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n')
write('ply_last_row_unterminated.ply', PLY_HEAD + '0 0 0\n1 0 0\n0 1 0\n3 0 1 2')
write('ply_nul_in_header.ply', PLY_HEAD.replace('element face 1', 'element face\0\0 1') + '0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n')
# Found by fuzz/MeshReaderFuzzer: "2/" (a slash and no texture index) made
# VTK's OBJ reader dereference its null texture-coordinate array.
write('obj_trailing_slash.obj', 'f 1 2/ 3\n' + TRI)
write('obj_texture_index_out_of_range.obj', TRI + 'vt 0 0\nf 1/1 2/2 3/1\n')
write('obj_mixed_index_forms.obj', TRI + 'vt 0 0\nf 1/1 2 3\n')
binary = ('ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\n'
          'property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n')
write('ply_binary_huge_count.ply', binary.encode() + struct.pack('<9f', 0, 0, 0, 1, 0, 0, 0, 1, 0))
write('ply_random_after_header.ply', PLY_HEAD.encode() + bytes((i * 37 + 11) % 256 for i in range(200)))
# Legacy VTK.
VTK_HEAD = '# vtk DataFile Version 3.0\nbad\nASCII\nDATASET POLYDATA\n'
write('vtk_index_too_large.vtk', VTK_HEAD + 'POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 9\n')
write('vtk_negative_index.vtk', VTK_HEAD + 'POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 -1 2\n')
write('vtk_truncated_points.vtk', VTK_HEAD + 'POINTS 3 float\n0 0 0 1 0\n')
write('vtk_huge_counts.vtk', VTK_HEAD + 'POINTS 2000000000 float\n0 0 0\n')
write('vtk_truncated_polygons.vtk', VTK_HEAD + 'POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0\n')
write('vtk_garbage.vtk', '# vtk DataFile Version 3.0\n' + 'x' * 100)
# Found by fuzz/MeshReaderFuzzer: more cells declared than the (format 5)
# offsets list, which overflowed every cell access.
write('vtk_more_cells_than_offsets.vtk', '# vtk DataFile Version 5.1\nbad\nASCII\nDATASET POLYDATA\n'
      'POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 70 3\nOFFSETS vtktypeint64\n0 3\n'
      'CONNECTIVITY vtktypeint64\n0 1 2\n')
# Found by fuzz/MeshReaderFuzzer in CI: a NUL byte in the DATASET line and
# a word among the POINTS values left VTK's reader with a half-built
# dataset it then dereferenced (SEGV in vtkPolyDataReader::ReadMeshSimple).
write('vtk_nul_in_header.vtk', b'# vtk DataFile Version 5.1\nvtk output\nASCII\nDATASET\0 POLYDATA\n'
      b'POINTS 3 double\n0 0 0 1 0 0 0 1 0\n')
write('vtk_word_in_points.vtk', VTK_HEAD + 'POINTS 3 double\n0 0 0 1 0 0 -0.FieldData 1\n')
TRI3 = 'POINTS 3 float\n0 0 0 1 0 0 0 1 0\n'
write('vtk_point_data_short.vtk', VTK_HEAD + TRI3 + 'POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 2\n'
      'SCALARS s float\nLOOKUP_TABLE default\n0 1\n')
write('vtk_cell_data_long.vtk', VTK_HEAD + TRI3 + 'POLYGONS 1 4\n3 0 1 2\nCELL_DATA 5\n'
      'SCALARS s float\nLOOKUP_TABLE default\n0 1 2 3 4\n')
write('vtk_string_array.vtk', VTK_HEAD + TRI3 + 'POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\n'
      'FIELD f 1\nnames 1 3 string\na\nb\nc\n')
write('vtk_metadata_information.vtk', VTK_HEAD + TRI3 + 'METADATA\nINFORMATION 1\n'
      'NAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA -5 1 1\n\nPOLYGONS 1 4\n3 0 1 2\n')
UG_HEAD = '# vtk DataFile Version 4.2\nbad\nASCII\nDATASET UNSTRUCTURED_GRID\n'
write('vtk_ug_type_mismatch.vtk', UG_HEAD + TRI3 + 'CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n12\n')
write('vtk_ug_no_cell_types.vtk', UG_HEAD + TRI3 + 'CELLS 1 4\n3 0 1 2\n')
write('vtk_ug_polyhedron.vtk', UG_HEAD + TRI3 + 'CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n42\n')
write('vtk_huge_dimensions.vtk', '# vtk DataFile Version 4.2\nbad\nASCII\nDATASET STRUCTURED_POINTS\n'
      'DIMENSIONS 100000 100000 100000\nSPACING 1 1 1\nORIGIN 0 0 0\n')
write('vtk_binary_truncated.vtk', b'# vtk DataFile Version 4.2\nbad\nBINARY\nDATASET POLYDATA\n'
      b'POINTS 3 float\n' + struct.pack('>5f', 0, 0, 0, 1, 0))
write('vtk_offsets_decreasing.vtk', '# vtk DataFile Version 5.1\nbad\nASCII\nDATASET POLYDATA\n'
      + TRI3 + 'POLYGONS 3 3\nOFFSETS vtktypeint64\n0 3 1\nCONNECTIVITY vtktypeint64\n0 1 2\n')
write('vtk_rectilinear_without_y.vtk', '# vtk DataFile Version 4.2\nbad\nASCII\n'
      'DATASET RECTILINEAR_GRID\nDIMENSIONS 3 4 2\nX_COORDINATES 3 double\n0 0.0 0.5\n')
# Found by fuzz/MeshReaderFuzzer: a coloured OFF without vertices (the
# largest colour value of none).
write('off_coloured_without_vertices.off', 'CNOFF\n0 0 2\n')
# STL.
write('stl_ascii_truncated.stl', 'solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n')
tri = struct.pack('<12fH', 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0)
write('stl_binary_count_too_large.stl', b'\0' * 80 + struct.pack('<I', 1000) + tri)
write('stl_binary_count_too_small.stl', b'\0' * 80 + struct.pack('<I', 1) + tri * 3)
# Found by fuzz/MeshReaderFuzzer: text that reads as an empty ASCII STL but
# that VTK takes for binary (NUL bytes) with a header count of billions.
write('stl_ascii_with_nul_bytes.stl', b'solid t\n' + b'\0' * 76 + b'\xff\xff\xff\x7f' + b'endsolid t\n')
write('stl_ascii_with_form_feeds.stl', b'solid t\n' + b'\x0c' * 76 + b'\xff\xff\xff\x7f' + b'endsolid t\n')
write('stl_nan.stl', 'solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex nan 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n')
# XML.
write('vtp_garbage.vtp', '<VTKFile type="PolyData"><PolyData><Piece NumberOfPoints="3"')
write('vtu_garbage.vtu', 'not xml at all')
# VTK XML: the block headers VTK's XML reader trusts (sizes, compression
# blocks), and the cell arrays it sizes its allocations from.
def vtp_ascii(offsets, connectivity, points='0 0 0 1 0 0 0 1 0', n_points=3, n_polys=1):
    return ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian">'
            '<PolyData><Piece NumberOfPoints="%d" NumberOfPolys="%d"><Points>'
            '<DataArray type="Float32" NumberOfComponents="3" format="ascii">%s</DataArray></Points>'
            '<Polys><DataArray type="Int64" Name="connectivity" format="ascii">%s</DataArray>'
            '<DataArray type="Int64" Name="offsets" format="ascii">%s</DataArray></Polys>'
            '</Piece></PolyData></VTKFile>\n' % (n_points, n_polys, points, connectivity, offsets))


write('vtp_index_out_of_range.vtp', vtp_ascii('3', '0 1 7'))
write('vtp_offsets_decreasing.vtp', vtp_ascii('3 2', '0 1 2', n_polys=2))
write('vtp_last_offset_huge.vtp', vtp_ascii('2000000000', '0 1 2'))
write('vtp_too_few_points.vtp', vtp_ascii('3', '0 1 2', points='0 0 0 1 0'))


def vtp_appended(points_header, payload, compressor=''):
    head = ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" '
            'header_type="UInt32"%s><PolyData><Piece NumberOfPoints="3" NumberOfPolys="1"><Points>'
            '<DataArray type="Float32" NumberOfComponents="3" format="appended" offset="0"/>'
            '</Points><Polys><DataArray type="Int64" Name="connectivity" format="ascii">0 1 2</DataArray>'
            '<DataArray type="Int64" Name="offsets" format="ascii">3</DataArray></Polys>'
            '</Piece></PolyData><AppendedData encoding="raw">\n_' % compressor)
    return head.encode() + points_header + payload + b'\n</AppendedData></VTKFile>\n'


coords = struct.pack('<9f', 0, 0, 0, 1, 0, 0, 0, 1, 0)
write('vtp_size_header_too_large.vtp', vtp_appended(struct.pack('<I', 4000000000), coords))
write('vtp_truncated_appended.vtp', vtp_appended(struct.pack('<I', 36), coords[:20]))
write('vtp_compression_blocks_huge.vtp', vtp_appended(struct.pack('<4I', 0x7fffffff, 32768, 36, 30),
                                                       b'x' * 30, ' compressor="vtkZLibDataCompressor"'))
write('vtp_compressed_garbage.vtp', vtp_appended(struct.pack('<4I', 1, 32768, 36, 30), b'x' * 30,
                                                  ' compressor="vtkZLibDataCompressor"'))
# Listing files (.vtm, .pvd): naming themselves, a missing block, nothing,
# a bad block among good ones, a non-numeric time step, truncated XML.
VTM = '<VTKFile type="vtkMultiBlockDataSet" version="1.0"><vtkMultiBlockDataSet>%s</vtkMultiBlockDataSet></VTKFile>\n'
PVD = '<VTKFile type="Collection" version="0.1"><Collection>%s</Collection></VTKFile>\n'
write('vtm_names_itself.vtm', VTM % '<DataSet index="0" file="vtm_names_itself.vtm"/>')
write('vtm_missing_block.vtm', VTM % '<DataSet index="0" file="no_such_block.vtp"/>')
write('vtm_no_blocks.vtm', VTM % '')
write('vtm_bad_block.vtm', VTM % '<DataSet index="0" file="vtp_index_out_of_range.vtp"/>')
write('vtm_truncated.vtm', (VTM % '<DataSet index="0" file="x.vtp"/>')[:60])
write('vtm_block_is_directory.vtm', VTM % '<DataSet index="0" file="."/>')
write('pvd_no_datasets.pvd', PVD % '')
write('pvd_bad_timestep.pvd', PVD % '<DataSet timestep="later" file="x.vtp"/>')
write('pvd_first_step_missing.pvd', PVD % '<DataSet timestep="0" file="gone.vtp"/>')
write('pvd_wrong_type.pvd', VTM % '<DataSet index="0" file="x.vtp"/>')
# Structured XML: a negative or overflowing extent, arrays shorter than it.
IMG = ('<VTKFile type="ImageData" version="1.0"><ImageData WholeExtent="%s" Origin="0 0 0" '
       'Spacing="1 1 1"><Piece Extent="%s"><PointData>%s</PointData></Piece></ImageData></VTKFile>\n')
write('vti_negative_extent.vti', IMG % ('0 4 0 4 0 4', '0 4 4 0 0 4', ''))
write('vti_huge_extent.vti', IMG % ('0 2000000000 0 2000000000 0 2000000000',
                                    '0 2000000000 0 2000000000 0 2000000000', ''))
write('vti_short_array.vti', IMG % ('0 2 0 2 0 2', '0 2 0 2 0 2',
                                    '<DataArray type="Float32" Name="s" format="ascii">1 2 3</DataArray>'))
# A small piece inside a 2e9^3 whole extent: the reader's output is sized by
# the whole extent (a fuzzer find: the surface filter asked for exabytes).
write('vti_huge_whole_extent.vti', '<VTKFile type="ImageData" version="1.0"><ImageData '
      'WholeExtent="0 2000000000 0 2000000000 0 2000000000" Origin="0 0 0" Spacing="1 1 1">'
      '<Piece Extent="0 2 0 2 0 0"><PointData></PointData></Piece></ImageData></VTKFile>\n')
write('vti_huge_implicit_piece.vti', '<VTKFile type="ImageData" version="1.0"><ImageData '
      'WholeExtent="0 1000 0 1000 0 1000" Origin="0 0 0" Spacing="1 1 1">'
      '<Piece Extent="0 1000 0 1000 0 1000"><PointData></PointData></Piece></ImageData></VTKFile>\n')
write('vti_garbage_extent.vti', IMG % ('a b c', 'a b c d e f', ''))
write('vts_no_points.vts', '<VTKFile type="StructuredGrid" version="1.0"><StructuredGrid WholeExtent="0 1 0 1 0 0">'
      '<Piece Extent="0 1 0 1 0 0"></Piece></StructuredGrid></VTKFile>\n')
write('vts_short_points.vts', '<VTKFile type="StructuredGrid" version="1.0"><StructuredGrid WholeExtent="0 1 0 1 0 0">'
      '<Piece Extent="0 1 0 1 0 0"><Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">'
      '0 0 0 1 0 0</DataArray></Points></Piece></StructuredGrid></VTKFile>\n')
write('vtr_short_coordinates.vtr', '<VTKFile type="RectilinearGrid" version="1.0"><RectilinearGrid WholeExtent="0 3 0 1 0 1">'
      '<Piece Extent="0 3 0 1 0 1"><Coordinates><DataArray type="Float32" format="ascii">0 1</DataArray>'
      '<DataArray type="Float32" format="ascii">0 1</DataArray><DataArray type="Float32" format="ascii">0 1</DataArray>'
      '</Coordinates></Piece></RectilinearGrid></VTKFile>\n')
# Exodus II: text, a netCDF signature over junk, an HDF5 signature over junk.
write('exo_text.exo', 'this is not exodus\n')
write('exo_netcdf_junk.e', b'CDF\x01' + bytes(range(256)) * 4)
write('exo_hdf5_junk.ex2', b'\x89HDF\r\n\x1a\n' + bytes(range(256)) * 4)
# Mutations of a valid ParaView-written file (fuzz/seeds/sphere.e): nodal
# results without their names (the Exodus library then leaves the names
# unset), a node number past num_nodes in the connectivity, cut short.
sphere = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'fuzz', 'seeds',
                           'sphere.e'), 'rb').read()
write('exo_results_without_names.e', sphere.replace(b'name_nod_var', b'name_xyz_var'))
write('exo_truncated.e', sphere[:len(sphere) // 2])
at = sphere.find(b'TRIANGLE') + 12  # connect1's type, vsize, then its 64-bit begin (CDF-2)
begin = struct.unpack('>Q', sphere[at + 8:at + 16])[0]
write('exo_node_out_of_range.e', sphere[:begin] + struct.pack('>i', 1000000) + sphere[begin + 4:])
# Optical data (refractiveindex.info YAML, for --nk): empty, an
# unsupported formula, a truncated row, outside the visible range, a
# Sellmeier pole at 500 nm, negative k, NaN.
write('nk_empty.yml', '')
write('nk_formula3.yml', 'DATA:\n  - type: formula 3\n    coefficients: 0 1 2 3\n')
write('nk_truncated.yml', 'DATA:\n  - type: tabulated nk\n    data: |\n        0.3 1.5 0\n        0.8 1.')
write('nk_infrared.yml', 'DATA:\n  - type: tabulated nk\n    data: |\n        1.0 1.5 0\n        2.0 1.5 0\n')
write('nk_pole.yml', 'DATA:\n  - type: formula 2\n    wavelength_range: 0.3 2.5\n'
      '    coefficients: 0 1 0.25 0 0 0 0\n')
write('nk_negative_k.yml', 'DATA:\n  - type: tabulated nk\n    data: |\n        0.3 1.5 -1\n        0.8 1.5 0\n')
write('nk_nan.yml', 'DATA:\n  - type: tabulated nk\n    data: |\n        0.3 nan 0\n        0.8 1.5 0\n')
# Random bytes with every extension.
noise = bytes((i * 131 + 7) % 256 for i in range(512))
for ext in ['obj', 'off', 'ply', 'vtk', 'stl', 'vtp', 'vtu', 'vtm', 'pvd', 'vts', 'vtr', 'vti', 'e',
            'yml']:
    write('random.' + ext, noise)
print(len(os.listdir(out)), 'files in', out)
