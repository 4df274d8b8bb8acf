# Run by Blender (blender -b --python blender_import.py -- FILE.glb): imports the file with
# Blender's own glTF importer and prints one line, "imported STONES OBJECTS X Y Z", the number of
# element objects, of all objects, and the largest |coordinate| of the elements' locations per
# axis, in Blender's units (metres, as glTF's). Used by tests/cli/client_programs_test.cpp.
import sys

import numpy

# Debian's Blender 3.4 importer still uses numpy.bool, which Debian's numpy no longer has.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

import bpy

path = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=path)
elements = [o for o in bpy.data.objects if o.type == "MESH" and o.name.startswith("element")]
extent = [max((abs(o.matrix_world.translation[axis]) for o in elements), default=0.0) for axis in range(3)]
print("imported %d %d %.9g %.9g %.9g" % (len(elements), len(bpy.data.objects), *extent))
