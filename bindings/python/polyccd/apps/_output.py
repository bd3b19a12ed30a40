"""The JSON that `polyccd check` and `polyccd index` print (docs/formats.md, "The command
line"): a Result or SceneResult as one JSON object."""
from ._json import result_json, time_json


def check_json(result, decide=False):
    """The JSON of `polyccd check` for a SceneResult or a Result (decide: of a scene
    solved in decide mode)."""
    if hasattr(result, "pairs"):
        return scene_json(result, decide)
    out = result_json(result)
    out["bodies"] = None  # bodies in contact: for scene files only
    return out


def contact_json(pair, c, decide=False):
    return {"bodies": list(pair.names), "a": list(c.a), "b": list(c.b),
            "first_contact": None if decide else time_json(c.first_contact)}


def scene_json(r, decide=False):
    """The JSON of a SceneResult (formats.md, check; "pairs" is an optional extension:
    every body pair in contact with its first time and touching features).

    decide: the result of decide mode (first_contact=False), which computes whether
    anything touches and a witness (the pair and features that stopped the solve), not
    when: every "first_contact" is then null, and the optional "mode": "decide" says
    why (the library's enclosure there may be the whole [0, 1], not a computed time)."""
    def when(t):
        return None if decide else time_json(t)
    out = {
        "collides": r.collides,
        "first_contact": when(r.first_contact),
        "features": [contact_json(p, c, decide) for p in r.first for c in p.contacts
                     if decide or r.first_contact.exact is None
                     or c.first_contact.exact == r.first_contact.exact],
        "bodies": list(r.first[0].names) if r.first else None,
        "pairs": [{"bodies": list(p.names), "first_contact": when(p.first_contact),
                   "features": [contact_json(p, c, decide) for c in p.contacts]}
                  for p in r.pairs],
    }
    if decide:
        out["mode"] = "decide"
    return out


def index_json(stored_name, query_name, r, all_contacts=False):
    """The JSON line of one query of `polyccd index`: the fields of `polyccd check` of the
    two-body scene (stored, query); with all_contacts, "features" lists every touching
    feature pair with its own first time."""
    out = scene_json(r)
    features = ([contact_json(p, c) for p in r.pairs for c in p.contacts] if all_contacts
                else out["features"])
    return {"stored": stored_name, "query": query_name, "collides": out["collides"],
            "first_contact": out["first_contact"], "features": features}
