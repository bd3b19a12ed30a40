"""A small arm as URDF text, for robot tests that need no mesh files: a base box, an upper
and a lower arm (boxes) on a shoulder and an elbow turning about z, each limited to
[-limit, limit], and with wrist=True a continuous wrist about x carrying an empty hand."""

LINKS = """  <link name="base"><collision><geometry><box size="0.4 0.4 0.2"/></geometry></collision></link>
  <link name="upper"><collision><origin xyz="0.5 0 0"/><geometry><box size="1 0.2 0.2"/></geometry></collision></link>
  <link name="lower"><collision><origin xyz="0.4 0 0"/><geometry><box size="0.8 0.1 0.1"/></geometry></collision></link>
"""
JOINTS = """  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.2"/><axis xyz="0 0 1"/><limit lower="-{0}" upper="{0}" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="lower"/>
    <origin xyz="1 0 0"/><axis xyz="0 0 1"/><limit lower="-{0}" upper="{0}" effort="1" velocity="1"/></joint>
"""
WRIST = """  <joint name="wrist" type="continuous"><parent link="lower"/><child link="hand"/>
    <origin xyz="0.8 0 0"/><axis xyz="1 0 0"/></joint>
  <link name="hand"/>
"""


def arm_urdf(limit=3, wrist=False):
    """The arm's URDF text (limit: the joint limits' magnitude, written as given)."""
    return ('<?xml version="1.0"?>\n<robot name="arm">\n' + LINKS + JOINTS.format(limit)
            + (WRIST if wrist else "") + "</robot>\n")
