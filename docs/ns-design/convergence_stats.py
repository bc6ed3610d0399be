import re, sys, statistics as st
for f in sys.argv[1:]:
    t = open(f).read()
    m = re.findall(r"CT ([0-9.]+) CP ([0-9.]+)", t.split("each stroke:")[1]) if "each stroke:" in t else []
    if not m: print(f, "no data"); continue
    ct = [float(a) for a, b in m]; cp = [float(b) for a, b in m]
    later = slice(2, None)
    eta = [a / b for a, b in zip(ct[later], cp[later])]
    n = len(ct[later])
    mct, mcp = st.mean(ct[later]), st.mean(cp[later])
    sct = st.stdev(ct[later]); scp = st.stdev(cp[later])
    print(f"{f}: strokes 3-{len(ct)}: CT {mct:.4f} (sd {sct:.4f}, {100*sct/mct:.1f}%; se {100*sct/mct/n**0.5:.1f}%), CP {mcp:.4f} (sd {100*scp/mcp:.1f}%), eta {mct/mcp:.4f}; first stroke CT {ct[0]:.4f} CP {cp[0]:.4f}")
