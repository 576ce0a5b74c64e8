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
#     ... --set time_step=wall --set fast_v0=V --set agitation=A --set agitation_vcrit=1e6
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
          --set wall_steps=32 --set fast_v0=$v --set agitation=$a --set agitation_vcrit=1e6
      done
    done ;;
  esac
done
/usr/bin/python3 - "$out" <<'PY'
import glob, json, os, sys
out = sys.argv[1]
def rows(path):
    lines = [l.rstrip("\n").split("\t") for l in open(path) if not l.startswith("#")]
    head = lines[0]
    return [dict(zip(head, l)) for l in lines[1:]]
def accel(series):
    pts = [(float(r["t"]), float(r["v_down"])) for r in rows(series)]
    if len(pts) < 3:
        return float("nan")
    t_end = pts[-1][0]
    last = [p for p in pts if p[0] >= t_end - 1.0]
    n = len(last)
    mt = sum(p[0] for p in last) / n
    mv = sum(p[1] for p in last) / n
    sxx = sum((p[0] - mt) ** 2 for p in last)
    return sum((p[0] - mt) * (p[1] - mv) for p in last) / sxx if sxx > 0 else float("nan")
names = {0: "steady", 1: "free fall", 2: "unsettled"}
def eq5_step(p, k, e):
    # Eq. (4): gamma_N from e_N for the free-wall pair (m_mean); dt = t_col of the lightest free-free
    # pair / steps_per_contact (scenarios/pipe_setup.cpp). For runs made before time_step existed.
    import math
    m, L = p["m_mean"], -math.log(e)
    gamma = 2 * L * math.sqrt(k / m) / math.sqrt(math.pi ** 2 + L ** 2)
    m_red = 0.5 * m * (1 - p["polydispersity"]) ** 2
    return math.pi / math.sqrt(k / m_red - 0.25 * gamma ** 2) / p["steps_per_contact"]
table = []
for run_dir in sorted(glob.glob(os.path.join(out, "*", "*", "bistable-pipe"))):
    part, name = run_dir.split(os.sep)[-3:-1]
    s = json.load(open(os.path.join(run_dir, "summary.json")))
    p = s["parameters"]
    ts = p.get("time_step", "eq5")
    rule = ("t_col/%g" % p["steps_per_contact"]) if ts == "eq5" else ("wall S=%g" % p["wall_steps"])
    for steady in glob.glob(os.path.join(run_dir, "tables", "steady_k*.tsv")):
        k = steady.split("steady_k")[1][:-4]
        for r in rows(steady):
            for start in ("slow", "fast"):
                e = r["e_N"]
                o = int(float(r["outcome_" + start]))
                v = float(r["v_" + start]) if o == 0 else float(r["v_last_" + start])
                ser = os.path.join(run_dir, "tables", "series_k%s_e%s_%s.tsv" % (k, e, start))
                a = accel(ser) if os.path.exists(ser) else float("nan")
                sx = float(r["sigma_vx_" + start])
                table.append((int(k), float(e), part, rule, start, p["fast_v0"] if start == "fast" else p["slow_v0"],
                              p["agitation"], names[o], v, float(r["t_end_" + start]), a,
                              float(r["steps_per_wall_" + start]) if "steps_per_wall_" + start in r
                              else p["wall_spacing"] / (abs(v) * eq5_step(p, float(k), float(e))),
                              sx, s["total_cpu_time_s"]))
table.sort(key=lambda x: (-x[0], x[1], x[4], x[2], x[3], x[5], x[6]))
print("| k_N | e_N | part | time step | start | v0 (m/s) | agitation (m/s) | outcome | speed (m/s) | t_end (s) | accel (m/s²) | steps/wall | σ_vx (m/s) | CPU s (run) |")
print("|---:|---:|---|---|---|---:|---:|---|---:|---:|---:|---:|---:|---:|")
for t in table:
    print("| %d | %.3g | %s | %s | %s | %g | %g | %s | %.4g | %.3g | %+.2f | %.3g | %.3g | %.0f |" % t)
with open(os.path.join(out, "bistable_pipe_dt.tsv"), "w") as f:
    f.write("k_N\te_N\tpart\trule\tstart\tv0\tagitation\toutcome\tspeed\tt_end\taccel\tsteps_per_wall\tsigma_vx\tcpu_run\n")
    for t in table:
        f.write("\t".join(str(x) for x in t) + "\n")
PY
