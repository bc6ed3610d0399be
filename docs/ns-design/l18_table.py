"""Tabulate the aerodynamic discipline's L18 rows of two design runs side by side.

Usage: l18_table.py RUN_A RUN_B NAME_A NAME_B [CYCLE] (cycle 1 unless given)."""
import json, math, sys

def load(run, cycle=1):
    return json.load(open(f"{run}/cycle-{cycle}/kinematics.json"))["result"]

def row(e):
    d = e["design"]
    r = e["result"]
    res = r.get("Ok") if isinstance(r, dict) else None
    key = (round(d["frequency_hz"], 3), round(d["amplitude_deg"], 2), round(d["mean_angle_deg"], 2), round(d["stroke_plane_deg"], 2))
    return key, res

def table(a, b, na, nb, cycle=1):
    ka, kb = load(a, cycle), load(b, cycle)
    print(f"| row | f Hz | amp ° | mean ° | plane ° | {na} CT net | {na} η net | {nb} CT net | {nb} η net |")
    print("|---|---|---|---|---|---|---|---|---|")
    for i, (ea, eb) in enumerate(zip(ka["runs"], kb["runs"])):
        (key, ra), (keyb, rb) = row(ea), row(eb)
        assert key == keyb, (key, keyb)
        f = lambda r, k: f"{r[k]:.4f}" if r else "failed"
        print(f"| {i+1} | {key[0]:g} | {key[1]:g} | {key[2]:g} | {key[3]:g} | {f(ra,'ct_net')} | {f(ra,'efficiency_net')} | {f(rb,'ct_net')} | {f(rb,'efficiency_net')} |")
    for name, k in ((na, ka), (nb, kb)):
        (key, r) = row(k["initial"])
        print(f"{name} initial {key}: CT net {r['ct_net']:.4f}, eta net {r['efficiency_net']:.4f}, cp {r['cp']:.4f}")
        for c in k["candidates"]:
            ck, cr = row(c["confirmation"])
            print(f"  {name} {c['method']}: {ck} combined {c['combined']} violation {c['violation']:.3f} CT {cr and cr['ct_net']} eta {cr and cr['efficiency_net']}")
        print(f"  chosen: {k['chosen']}; pareto {len(k['pareto'])} points; surface quality {k['surface_quality']}")
        print("  level means:", [[round(v, 3) for v in lm] for lm in k["level_means"]])

if __name__ == "__main__":
    table(sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5]) if len(sys.argv) > 5 else 1)
