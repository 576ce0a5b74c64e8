#!/usr/bin/env bash
# Issue 42: does Fig. 6's fast branch converge in the time step? Paper pipe, default wall (1.3 mm),
# elastic reading of Eq. (2), 10 m/s fast starts; every run is one granrepro command:
#
#   fixed steps (Eq. 5 and finer), dt = t_col/SPC of the stiffest pair, SPC = 50, 100, 200, 400:
#     granrepro bistable-pipe --scale paper --set kN_list=K --set eN_list=E --set time_step=eq5 \
#       --set steps_per_contact=SPC --set budget_min=40 --set v_abort=1000 --set length_check=0
#   the wall rule, dt = min(t_col/50, wall_spacing / (S v_max)), S = 16, 32, 64:
#     granrepro bistable-pipe --scale paper --set kN_list=K --set eN_list=E --set time_step=wall \
#       --set wall_steps=S --set length_check=0
#   starts on the Eq. (5) fast branch (the wall rule, S = 32): fast_v0 = the Eq. (5) state's speed,
#   agitation A = 0.3, 1 and 3 m/s (agitation_vcrit lifted so that A is used as given):
#     ... --set time_step=wall --set fast_v0=V --set agitation=A --set agitation_vcrit=1e6 --set dt_check_eN=0
#   (each such run also makes the same start at Eq. (5)'s step, the *_fast_eq5 columns)
#
# PARTS selects (default all): fixed, wall, branch. Runs go to $OUT/<part>/<name>/ (default
# out-studies/bistable-pipe-dt); a finished run is reused. Then one table row per start:
#   scripts/studies/bistable_pipe_dt.sh > scripts/studies/bistable_pipe_dt.md
# (steps/wall: time steps while the plug passes one wall grain at its last speed; accel: the
# slope of the mean speed over the run's last second, + = speeding up). The fixed SPC = 50 row is
# the paper-scale Fig. 6 run itself (paper_figures/). Table columns in bistable_pipe_dt.tsv, drawn
# by bistable_pipe_dt.gp.
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${GRANREPRO:-./build/granrepro}
out=${OUT:-out-studies/bistable-pipe-dt}
parts=${PARTS:-fixed wall branch}
run() { # part, name, options...
  local dir="$out/$1/$2"
  shift 2
  [ -f "$dir/bistable-pipe/summary.json" ] && return 0
  "$bin" bistable-pipe --scale paper --set length_check=0 "$@" --threads "${THREADS:-2}" --quiet --out "$dir" \
    > /dev/null || true
}
for part in $parts; do
  case $part in
  fixed)
    for spc in ${SPC_LIST:-50 100 200 400}; do
      for k in 2000 200; do
        en=$([ $k = 2000 ] && echo 0.5,0.7,0.9,0.95 || echo 0.7,0.95)
        run fixed "k${k}_spc$spc" --set kN_list=$k --set "eN_list=$en" --set time_step=eq5 \
          --set steps_per_contact=$spc --set budget_min=40 --set v_abort=1000
      done
    done ;;
  wall)
    for s in ${S_LIST:-16 32 64}; do
      for k in 2000 200; do
        en=$([ $k = 2000 ] && echo 0.5,0.7,0.9,0.95 || echo 0.7,0.95)
        run wall "k${k}_S$s" --set kN_list=$k --set "eN_list=$en" --set time_step=wall --set wall_steps=$s
      done
    done ;;
  branch)
    # k_N e_N v0: the Eq. (5) fast states of paper_figures (t_col/50)
    for kev in 2000:0.9:183 2000:0.95:244 200:0.95:154; do
      IFS=: read -r k e v <<< "$kev"
      for a in ${A_LIST:-0.3 1 3}; do
        run branch "k${k}_e${e}_v${v}_a$a" --set kN_list=$k --set "eN_list=$e" --set time_step=wall \
          --set wall_steps=32 --set fast_v0=$v --set agitation=$a --set agitation_vcrit=1e6 --set dt_check_eN=0
      done
    done ;;
  esac
done
/usr/bin/python3 - "$out" ${EXTRA:-} <<'PY'
# One row per start of every run under $out/<part>/<name>/ (and of the results folders named
# after it, e.g. paper_figures for t_col/50), read from data.h5 and summary.json.
import glob, json, math, os, sys
import h5py
names = {0: "steady", 1: "free fall", 2: "unsettled"}
def eq5_step(p, k, e):
    # Eq. (4): gamma_N from e_N for the free-wall pair (m_mean); dt = t_col of the lightest free-free
    # pair / steps_per_contact (scenarios/pipe_setup.cpp). For runs made before time_step existed.
    m, L = p["m_mean"], -math.log(e)
    gamma = 2 * L * math.sqrt(k / m) / math.sqrt(math.pi ** 2 + L ** 2)
    m_red = 0.5 * m * (1 - p["polydispersity"]) ** 2
    return math.pi / math.sqrt(k / m_red - 0.25 * gamma ** 2) / p["steps_per_contact"]
def accel(t, v):
    # slope of the mean speed over the last second of the run
    pts = [(a, b) for a, b in zip(t, v) if a >= t[-1] - 1.0]
    n = len(pts)
    if n < 3:
        return float("nan")
    mt, mv = sum(a for a, _ in pts) / n, sum(b for _, b in pts) / n
    sxx = sum((a - mt) ** 2 for a, _ in pts)
    return sum((a - mt) * (b - mv) for a, b in pts) / sxx
out, extra = sys.argv[1], sys.argv[2:]
folders = sorted(glob.glob(os.path.join(out, "*", "*", "bistable-pipe"))) + [os.path.join(x, "bistable-pipe") for x in extra]
table = []
for run_dir in folders:
    label = os.path.relpath(os.path.dirname(run_dir), out) if run_dir.startswith(out) else os.path.dirname(run_dir)
    s = json.load(open(os.path.join(run_dir, "summary.json")))
    p = {k: (v["value"] if isinstance(v, dict) else v) for k, v in s["parameters"].items()}
    ts = p.get("time_step", "eq5")
    rule = ("t_col/%g" % p["steps_per_contact"]) if ts == "eq5" else ("wall S=%g" % p["wall_steps"])
    h = h5py.File(os.path.join(run_dir, "data.h5"), "r")
    for tname in sorted(h["tables"]):
        if not tname.startswith("steady_k"):
            continue
        k, tab = tname[len("steady_k"):], h["tables"][tname]
        starts = [("slow", "slow", rule), ("fast", "fast", rule)]
        if "v_fast_eq5" in tab and ts == "wall":
            starts.append(("fast_eq5", "fast", "t_col/%g (beside)" % p["steps_per_contact"]))
        for i, e in enumerate(tab["e_N"][:]):
            for col, start, rl in starts:
                o = tab["outcome_" + col][i]
                if o != o:
                    continue
                o = int(o)
                v = tab["v_" + col][i] if o == 0 else tab["v_last_" + col][i]
                suffix = {"slow": "_slow", "fast": "_fast", "fast_eq5": "_fast_eq5"}[col]
                ser = "series_k%s_e%s%s" % (k, ("%.10g" % e), suffix)
                # the acceleration tells a run that did not settle (a steady run's last second holds its approach)
                a = accel(h["tables"][ser]["t"][:], h["tables"][ser]["v_down"][:]) if ser in h["tables"] and o != 0 else float("nan")
                spw = tab["steps_per_wall_" + col][i] if "steps_per_wall_" + col in tab else \
                    p["wall_spacing"] / (abs(v) * eq5_step(p, float(k), float(e)))
                sx = tab["sigma_vx_" + col][i]
                t_end = tab["t_end_" + col][i] if "t_end_" + col in tab else float("nan")
                table.append((s["scale"], int(float(k)), float(e), label, rl, start,
                              p["fast_v0"] if start == "fast" else p["slow_v0"], p["agitation"], names[o], v, t_end, a,
                              spw, sx))
table.sort(key=lambda x: (x[0], -x[1], x[2], x[5], x[4], x[6], x[7], x[3]))
print("| scale | k_N | e_N | run | time step | start | v0 (m/s) | agitation (m/s, before the v_crit cap) | outcome | speed (m/s) | t_end (s) | accel (m/s², not steady) | steps/wall | σ_vx (m/s) |")
print("|---|---:|---:|---|---|---|---:|---:|---|---:|---:|---:|---:|---:|")
for t in table:
    print(("| %s | %d | %.3g | %s | %s | %s | %g | %g | %s | %.4g | %.3g | %+.2f | %.3g | %.3g |" % t).replace("+nan", "–").replace("nan", "–"))
with open(os.path.join(out, "bistable_pipe_dt.tsv"), "w") as f:
    f.write("scale\tk_N\te_N\trun\trule\tstart\tv0\tagitation\toutcome\tspeed\tt_end\taccel\tsteps_per_wall\tsigma_vx\n")
    for t in table:
        f.write("\t".join(str(x) for x in t) + "\n")
PY
