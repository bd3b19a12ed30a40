"""polyccd.apps: the applications built on the polyccd bindings.

The command line (cli, `polyccd ...`), the CSV query-set and JSON case/scene readers
(_csv, _json, _scene_file), the corpus and query-set runners (_corpus, _queries), the
example-data loaders (_data: trimesh, gemmi), the scene renderer (_render: matplotlib)
and the demo (_demo*). `import polyccd` never imports this package; each optional
third-party module is imported only by the function that needs it.
"""
