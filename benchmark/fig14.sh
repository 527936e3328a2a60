#!/usr/bin/env bash
# The paper's Fig. 14: D_area along the iterations with the adaptive step
# against a fixed step of 0.01, on one plot. Three runs of `dlf disk` on one
# mesh (default nefertiti, circle, Tutte start): the literal Algorithm 1 with
# the step of Eq. 5, the literal Algorithm 1 with the fixed step 0.01, and
# the stabilised paper mode; the plot (log scale of D_area − 2) goes to
# doc/images/fig14_MESH.svg, the last values to stdout.
#
#   benchmark/fig14.sh                       # nefertiti
#   MESH=mushroom BORDER=square benchmark/fig14.sh
#
# DLF (default build/tools/dlf) and MESHES (default build/data/meshes).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
DLF="${DLF:-build/tools/dlf}"
MESHES="${MESHES:-build/data/meshes}"
MESH="${MESH:-nefertiti}"
BORDER="${BORDER:-circle}"
MAX_IT="${MAX_IT:-500}"
[[ -x "$DLF" ]] || { echo "fig14: $DLF not built" >&2; exit 2; }
export OMP_THREAD_LIMIT=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
common=("$MESHES/$MESH.off" --border "$BORDER" --max-iterations "$MAX_IT" --history -q)
"$DLF" disk "${common[@]}" --mode literal --report "$tmp/adaptive.json" >/dev/null 2>&1 || true
"$DLF" disk "${common[@]}" --mode literal --fixed-step 0.01 --report "$tmp/fixed.json" >/dev/null 2>&1 || true
"$DLF" disk "${common[@]}" --mode paper --report "$tmp/paper.json" >/dev/null 2>&1 || true
mkdir -p doc/images
python3 - "$tmp" "doc/images/fig14_$MESH.svg" "$MESH" "$BORDER" <<'EOF'
import json, math, sys
tmp, out, mesh, border = sys.argv[1:5]
runs = [("adaptive.json", "literal, adaptive (Eq. 5, μ 0.8)", "#d62728"),
        ("fixed.json", "literal, fixed 0.01", "#1f77b4"),
        ("paper.json", "paper mode (stabilised)", "#2ca02c")]
series = []
for f, label, colour in runs:
    r = json.load(open(f"{tmp}/{f}"))
    ys = [r["initial_domain_d_area"]] + [h["d_area"] for h in r.get("history", [])]
    series.append((label, colour, ys, r))
    print(f"{label}: {r['stop_reason']} after {r['iterations']} iterations, D_area "
          f"{r['initial_domain_d_area']:.4f} -> {r['domain_d_area']:.4f}")
W, H, L, B = 720, 420, 70, 50
xmax = max(len(s[2]) - 1 for s in series) or 1
vals = [y - 2 for s in series for y in s[2] if y - 2 > 0]
lo = math.floor(math.log10(min(vals))); hi = math.ceil(math.log10(max(vals)))
hi = max(hi, lo + 1)
X = lambda i: L + (W - L - 20) * i / xmax
Y = lambda y: 20 + (H - B - 20) * (hi - math.log10(max(y - 2, 10 ** lo))) / (hi - lo)
svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
       f'<rect width="{W}" height="{H}" fill="white"/>',
       f'<text x="{W/2}" y="14" text-anchor="middle">{mesh}, {border}: D_area − 2 per iteration (the paper\'s Fig. 14)</text>']
for e in range(lo, hi + 1):
    svg.append(f'<line x1="{L}" x2="{W-20}" y1="{Y(2 + 10**e):.1f}" y2="{Y(2 + 10**e):.1f}" stroke="#ddd"/>')
    svg.append(f'<text x="{L-6}" y="{Y(2 + 10**e)+4:.1f}" text-anchor="end">1e{e}</text>')
for k in range(6):
    i = round(xmax * k / 5)
    svg.append(f'<text x="{X(i):.1f}" y="{H-B+16}" text-anchor="middle">{i}</text>')
svg.append(f'<text x="{(L+W)/2}" y="{H-12}" text-anchor="middle">iteration</text>')
for n, (label, colour, ys, r) in enumerate(series):
    pts = " ".join(f"{X(i):.1f},{Y(y):.1f}" for i, y in enumerate(ys))
    svg.append(f'<polyline fill="none" stroke="{colour}" stroke-width="1.5" points="{pts}"/>')
    svg.append(f'<text x="{W-30}" y="{40 + 16*n}" text-anchor="end" fill="{colour}">{label}: {r["stop_reason"]}, '
               f'{r["iterations"]} it., {r["domain_d_area"]:.3f}</text>')
svg.append("</svg>")
open(out, "w").write("\n".join(svg) + "\n")
print("wrote", out)
EOF
