"""Independent check of a templated mesh (.tmesh, JSON): every vertex pair its identification
tables name is one point of AT — the two instances' transformations send the two template
vertices to the same place, up to the rounding of the transformations (1e-9 relative). The
Lemma 4.2 certificate is combinatorial (it numbers AT's vertices through the SVB), so a pair
identified at two different places passes it; this check looks at the coordinates.
Prints the number of pairs checked and of pairs at different points; exit 1 when there is one.
Usage: identified_points_check.py MESH.tmesh"""
import json
import sys


def main(path):
    t = json.load(open(path))
    d = t["dimension"]
    instances = [(ti, i["transformation"]) for ti, tm in enumerate(t["templates"])
                 for i in tm["instances"]]

    def image(k, v):
        ti, f = instances[k]
        p = t["templates"][ti]["vertices"][v]
        m, b = t["transformations"][f]["matrix"], t["transformations"][f]["translation"]
        return [sum(m[r * d + c] * p[c] for c in range(d)) + b[r] for r in range(d)]

    pairs, bad = 0, []
    for from_instance, to_instance, table in t["identifications"]:
        for a, b in t["identification_tables"][table]["pairs"]:
            pairs += 1
            x, y = image(from_instance, a), image(to_instance, b)
            if any(abs(x[k] - y[k]) > 1e-9 * (1 + abs(x[k])) for k in range(d)):
                bad.append((from_instance, a, to_instance, b, x, y))
    print(f"{pairs} identified pairs, {len(bad)} at different points"
          + (": instance %d vertex %d at %s, instance %d vertex %d at %s"
             % (bad[0][0], bad[0][1], bad[0][4], bad[0][2], bad[0][3], bad[0][5]) if bad else ""))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
