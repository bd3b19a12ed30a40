{
 "format": "polyccd-robot/1",
 "name": "solid-link-holds-obstacle-at-zero",
 "source": "issue 33 (found by tests/test_robot_min_distance_ur5.py): the robot filter's first-contact window raised a solid pair's bound from 0 (a link holding an obstacle at t = 0) to its surface bound, reporting the first contact where the link's surface left the cube (t = 3301/4096) instead of t = 0",
 "urdf": "<?xml version=\"1.0\"?>\n<robot name=\"arm\">\n  <link name=\"base\"><collision><geometry><box size=\"0.4 0.4 0.2\"/></geometry></collision></link>\n  <link name=\"upper\"><collision><origin xyz=\"0.5 0 0\"/><geometry><box size=\"1 0.2 0.2\"/></geometry></collision></link>\n  <link name=\"lower\"><collision><origin xyz=\"0.4 0 0\"/><geometry><box size=\"0.8 0.1 0.1\"/></geometry></collision>\n                     <collision><origin xyz=\"0.8 0 0\" rpy=\"0 0 0.5\"/><geometry><sphere radius=\"0.08\"/></geometry></collision></link>\n  <joint name=\"shoulder\" type=\"revolute\"><parent link=\"base\"/><child link=\"upper\"/>\n    <origin xyz=\"0 0 0.2\" rpy=\"0 0 0\"/><axis xyz=\"0 0 1\"/><limit lower=\"-6\" upper=\"6\" effort=\"1\" velocity=\"1\"/></joint>\n  <joint name=\"elbow\" type=\"revolute\"><parent link=\"upper\"/><child link=\"lower\"/>\n    <origin xyz=\"1 0 0\" rpy=\"0 0 0\"/><axis xyz=\"0 0 1\"/><limit lower=\"-6\" upper=\"6\" effort=\"1\" velocity=\"1\"/></joint>\n</robot>\n",
 "q0": [
  0.7853981633974483,
  0.0
 ],
 "q1": [
  1.0,
  0.3
 ],
 "options": {
  "self_collision": false
 },
 "obstacles": [
  {
   "name": "cube",
   "mesh": {
    "vertices": [
     [
      "33355/100000",
      "33355/100000",
      "19/100"
     ],
     [
      "37355/100000",
      "33355/100000",
      "19/100"
     ],
     [
      "33355/100000",
      "37355/100000",
      "19/100"
     ],
     [
      "37355/100000",
      "37355/100000",
      "19/100"
     ],
     [
      "33355/100000",
      "33355/100000",
      "21/100"
     ],
     [
      "37355/100000",
      "33355/100000",
      "21/100"
     ],
     [
      "33355/100000",
      "37355/100000",
      "21/100"
     ],
     [
      "37355/100000",
      "37355/100000",
      "21/100"
     ]
    ],
    "triangles": [
     [
      0,
      2,
      1
     ],
     [
      1,
      2,
      3
     ],
     [
      4,
      5,
      6
     ],
     [
      5,
      7,
      6
     ],
     [
      0,
      1,
      4
     ],
     [
      1,
      5,
      4
     ],
     [
      2,
      6,
      3
     ],
     [
      3,
      6,
      7
     ],
     [
      0,
      4,
      2
     ],
     [
      2,
      4,
      6
     ],
     [
      1,
      3,
      5
     ],
     [
      3,
      7,
      5
     ]
    ]
   }
  }
 ],
 "expect": {
  "collides": true,
  "first_contact": "0"
 }
}