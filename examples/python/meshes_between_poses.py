# Two meshes, one moving between a start and an end pose: does it ever touch the other,
# and when first? (trimesh builds the meshes; any object with .vertices and .faces works.)
import trimesh

import polyccd

mover = polyccd.Mesh.from_trimesh(trimesh.creation.box(extents=(1, 1, 1)))
wall = polyccd.Mesh.from_trimesh(trimesh.creation.box(extents=(0.2, 4, 4)))

# Poses as (position, quaternion w x y z), or as 4x4 matrices: the box slides from
# x = -3 to x = 3 and turns a quarter turn about z on the way.
start, end = ((-3, 0, 0), (1, 0, 0, 0)), ((3, 0, 0), (1, 0, 0, 1))
result = polyccd.check([polyccd.Body(mover, polyccd.Motion.between(start, end), name="box"),
                        polyccd.Body(wall, name="wall")])

print(result.collides, f"{result.first_contact.approx:.6f}")
for contact in result.pairs[0].contacts[:2]:
    print(contact.a, contact.b)

# Prints:
#   True 0.365896
#   ('vertex', 4) ('triangle', 2)
#   ('vertex', 5) ('triangle', 0)
