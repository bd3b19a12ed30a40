"""A rigid MuJoCo scene where discrete contacts let a fast thin object tunnel (issue 22,
item 4): a spinning box "bullet" (2 x 4 x 4 cm) shot at 30 m/s through a fixed plate
1 cm thick, no gravity, a 5 ms step: the bullet moves 15 cm per step, farther than
bullet and plate together are thick. MuJoCo (PyPI
`mujoco`) steps the model and detects contacts only between overlapping (or within
margin) geoms at each step, so it records none and the bullet passes through.

Each step is then turned into exact polyccd motions: the bullet's body position and
quaternion (data.xpos, data.xquat: w, x, y, z) before and after the step give
polyccd.Motion.between(pose0, pose1) (floats at their exact values), its box mesh in body
coordinates is its geom (centred, unrotated), the plate is a static mesh at its world
pose. polyccd.check decides each step exactly.

Used by tests/test_step_tunnel.py (the answers) and bench_step.py (a row: MuJoCo's
contacts, polyccd's first time and pair, time per step)."""
import numpy as np

BULLET = (0.01, 0.02, 0.02)  # half extents (MuJoCo box size)
PLATE = (0.005, 0.3, 0.3)    # half extents; the plate's faces at x = +-0.005
START_X, SPEED, SPIN, DT, STEPS = -0.2, 30.0, (5.0, 40.0, 25.0), 0.005, 20

XML = f"""
<mujoco>
  <option timestep="{DT}" gravity="0 0 0"/>
  <worldbody>
    <geom name="plate" type="box" size="{PLATE[0]} {PLATE[1]} {PLATE[2]}" pos="0 0 0"/>
    <body name="bullet" pos="{START_X} 0.01 -0.02">
      <freejoint/>
      <geom name="bullet" type="box" size="{BULLET[0]} {BULLET[1]} {BULLET[2]}" mass="0.01"/>
    </body>
  </worldbody>
</mujoco>"""


def box_mesh(half):
    """(vertices (8, 3), faces (12, 3)) of the box [-h, h]^3, faces outward."""
    hx, hy, hz = half
    v = np.array([[sx * hx, sy * hy, sz * hz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
    f = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                  [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    return v, f


def simulate():
    """[(position, quaternion w x y z)] of the bullet at steps 0..STEPS and MuJoCo's
    contact count after each step (data.ncon)."""
    import mujoco
    model = mujoco.MjModel.from_xml_string(XML)
    data = mujoco.MjData(model)
    body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, "bullet")
    data.qvel[:3] = (SPEED, 0, 0)
    data.qvel[3:6] = SPIN  # angular velocity (local frame)
    mujoco.mj_forward(model, data)
    poses = [(data.xpos[body].copy(), data.xquat[body].copy())]
    contacts = []
    for _ in range(STEPS):
        mujoco.mj_step(model, data)
        # mj_step's positions and contacts are those before its integration: the new
        # state's come from mj_forward (kinematics and collision detection).
        mujoco.mj_forward(model, data)
        contacts.append(int(data.ncon))
        poses.append((data.xpos[body].copy(), data.xquat[body].copy()))
    return poses, contacts


def polyccd_steps(poses):
    """[(step k, polyccd.check result)] of every step k: poses[k] -> poses[k + 1]."""
    import polyccd
    bv, bf = box_mesh(BULLET)
    pv, pf = box_mesh(PLATE)
    bullet, plate = polyccd.Mesh(bv, bf), polyccd.Mesh(pv, pf)
    out = []
    for k in range(len(poses) - 1):
        (p0, q0), (p1, q1) = poses[k], poses[k + 1]
        motion = polyccd.Motion.between((p0.tolist(), q0.tolist()), (p1.tolist(), q1.tolist()))
        out.append((k, polyccd.check([polyccd.Body(bullet, motion, name="bullet"),
                                      polyccd.Body(plate, name="plate")])))
    return out
