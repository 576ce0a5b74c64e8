#include "bench/soft_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "analysis/seed_stats.hpp"
#include "core/spawn.hpp"
#include "scenarios/pipe_setup.hpp"

namespace granrepro {

namespace {

using Engine = PipeEngine<LinearSpringDashpot, CoulombShear>;

// The Fig. 6 pipe of the bench: width 2 cm, wall grains 0.66 mm at 1 mm spacing, k_N = 2000 N/m,
// e_N = 0.95, mu = 0.5, area fraction 0.55, slow start; `length` sets the number of grains
// (0.111 m: 1498 free grains).
PipeSpec bench_spec(double length) {
    PipeSpec s;
    s.geo.wall_spacing = 1.0e-3;
    s.geo.length = std::round(length / s.geo.wall_spacing) * s.geo.wall_spacing;
    s.e_N = 0.95;
    // gran/hooke caps the shear force at mu |F_N| of the whole normal force (dashpot included): the
    // magnitude reading of Eq. (2). Whatever reading the experiments use, the comparison with
    // LAMMPS runs this one.
    s.friction_normal = FrictionNormal::Magnitude;
    return s;
}

double load_average() {
    double l[1] = {NAN};
    return getloadavg(l, 1) == 1 ? l[0] : NAN;
}

// Process CPU seconds, all threads (glibc's clock is CLOCK_PROCESS_CPUTIME_ID).
double cpu_now() { return double(std::clock()) / CLOCKS_PER_SEC; }

struct Timing {
    double wall = NAN, cpu = NAN; // [s]
};

struct Series {
    std::vector<double> wall, cpu; // [s]
    void add(const Timing& t) {
        wall.push_back(t.wall);
        cpu.push_back(t.cpu);
    }
};

Timing time_advance(Engine& eng, long steps) {
    const double c0 = cpu_now();
    const auto t0 = std::chrono::steady_clock::now();
    eng.advance(steps);
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), cpu_now() - c0};
}

// Times `timed` steps after `warm` untimed ones; `builds`: the list builds per 1000 timed steps.
Timing time_window(Engine& eng, long warm, long timed, double& builds) {
    eng.advance(warm);
    const long b0 = eng.list_builds();
    const Timing tm = time_advance(eng, timed);
    builds = double(eng.list_builds() - b0) * 1000.0 / double(timed);
    return tm;
}


// ---- LAMMPS ----------------------------------------------------------------------------------

struct Lammps {
    std::string lmp;                 // the binary, empty if absent
    std::string version;             // first line of its output
    std::string why_not;             // why the comparison is skipped
};

Lammps find_lammps() {
    Lammps l;
    for (const char* b : {"lmp", "lmp_serial", "lmp_openmpi", "lmp_mpich", "lmp_mpi"})
        if (l.lmp = find_in_path(b); !l.lmp.empty()) break;
    if (l.lmp.empty()) {
        l.why_not = "LAMMPS is not installed (no lmp, lmp_serial, lmp_openmpi on PATH; Debian package lammps)";
        return l;
    }
    // With no input (stdin is /dev/null) LAMMPS prints its version line and stops.
    const std::string out = program_output({l.lmp, "-log", "none"});
    l.version = out.substr(0, out.find('\n'));
    return l;
}

// Writes pipe.data (the engine's present state: free grains type 1, wall grains type 2) and
// in.pipe, the same physics in pair gran/hooke:
//   F_n = k_n delta - m_eff gamma_n v_n                         = Eq. (1), gamma_n = gamma_N;
//   F_t = -min(mu |F_n|, m_eff gamma_t |v_t|) v_t / |v_t|       with dampflag 1 and gamma_t = 1e12 1/s
//         this is mu |F_n| sgn(v_t), Eq. (2) in the magnitude reading, except below
//         |v_t| = mu |F_n| / (m_eff gamma_t) ~ 1e-9 m/s, where it falls linearly to 0;
//   fix freeze on the wall grains: zero force, and gran/hooke then uses m_eff = m of the free
//   grain (infinite wall mass); fix nve on the free grains only (no rotation: omega stays 0, so
//   v_t has no rolling part); enforce2d; gravity on the free grains; the same dt and skin (LAMMPS
//   rebuilds when a grain moved skin/2, we when one moved skin/2 relative to the mean: lists
//   only, no physics). The one difference in the integrator: LAMMPS evaluates the dashpot and
//   friction at the half-step velocity, we at the predicted full-step velocity (pipe_engine.hpp).
// dump_every > 0 adds a dump of the free grains (id mass x y vx vy) every dump_every steps.
void write_lammps_case(const std::filesystem::path& dir, const Engine& eng, const PipeSpec& spec, long steps,
                       long dump_every) {
    const LinearSpringDashpot law = pipe_law(spec.k_N, spec.e_N, spec.m_mean);
    const long n_free = long(eng.size());
    const long n_row = std::lround(spec.geo.length / spec.geo.wall_spacing);
    std::ofstream data(dir / "pipe.data");
    data.precision(17);
    data << "granrepro pipe\n\n" << n_free + 2 * n_row << " atoms\n2 atom types\n\n"
         << -2e-3 << " " << spec.geo.width + 2e-3 << " xlo xhi\n0 " << spec.geo.length << " ylo yhi\n"
         << "-0.5e-3 0.5e-3 zlo zhi\n\nAtoms # sphere\n\n";
    // LAMMPS reads a data file's density per volume, m = density * 4/3 pi r^3, also in 2d (the
    // trajectory check below compares the masses it reports with ours).
    for (long i = 0; i < n_free; ++i) {
        const std::size_t k = std::size_t(i);
        const double r = eng.radius()[k];
        data << i + 1 << " 1 " << 2 * r << " " << eng.mass()[k] / (4.0 / 3.0 * M_PI * r * r * r) << " "
             << eng.x()[k] << " " << eng.y()[k] << " 0\n";
    }
    for (long k = 0; k < 2 * n_row; ++k) {
        const bool right = k >= n_row;
        double y = (right ? spec.geo.right_row_shift : 0.0) + double(k % n_row) * spec.geo.wall_spacing;
        y = std::fmod(y, spec.geo.length);
        if (y < 0) y += spec.geo.length;
        data << n_free + k + 1 << " 2 " << 2 * spec.geo.wall_radius << " 1000 " << (right ? spec.geo.width : 0.0)
             << " " << y << " 0\n";
    }
    data << "\nVelocities\n\n";
    for (long i = 0; i < n_free; ++i)
        data << i + 1 << " " << eng.vx()[std::size_t(i)] << " " << eng.vy()[std::size_t(i)] << " 0 0 0 0\n";
    for (long k = 0; k < 2 * n_row; ++k) data << n_free + k + 1 << " 0 0 0 0 0 0\n";

    std::ofstream in(dir / "in.pipe");
    in.precision(17);
    in << "units si\ndimension 2\nboundary f p p\natom_style sphere\nread_data pipe.data\n"
       << "group free type 1\ngroup wall type 2\n"
       << "pair_style gran/hooke " << law.k_N << " 0 " << law.gamma_N << " 1e12 " << spec.mu << " 1\n"
       << "pair_coeff * *\n"
       << "neighbor " << spec.skin << " bin\nneigh_modify delay 0 every 1 check yes exclude type 2 2\n"
       << "comm_modify vel yes\n"
       << "fix grav free gravity " << spec.geo.gravity << " vector 0 -1 0\n"
       << "fix integrate free nve\nfix frz wall freeze\nfix twod all enforce2d\n"
       << "timestep " << eng.dt() << "\nthermo " << std::max(steps, 1L) << "\n";
    if (dump_every > 0)
        in << "dump traj free custom " << dump_every << " traj.dump id mass x y vx vy\n"
           << "dump_modify traj sort id format float %.17g\n";
    in << "run " << steps << "\n";
}

struct LammpsRun {
    Timing time; // wall: "Loop time"; cpu: loop time x CPU use x tasks [s]
    long neighbor_builds = -1;
};

LammpsRun run_lammps(const Lammps& l, const std::filesystem::path& dir) {
    const std::vector<std::string> argv = {l.lmp, "-in", "in.pipe", "-log", "none"};
    const int rc = run_program(argv, dir, dir / "lmp.out");
    LammpsRun r;
    std::ifstream out(dir / "lmp.out");
    for (std::string line; std::getline(out, line);) {
        if (line.rfind("Loop time of ", 0) == 0) r.time.wall = std::atof(line.c_str() + 13);
        const auto pct = line.find("% CPU use with ");
        if (pct != std::string::npos) {
            const double use = std::atof(line.c_str()) / 100.0;
            const long tasks = std::atol(line.c_str() + pct + 15);
            r.time.cpu = r.time.wall * use * double(tasks);
        }
        if (line.rfind("Neighbor list builds = ", 0) == 0) r.neighbor_builds = std::atol(line.c_str() + 23);
    }
    if (rc != 0 || !(r.time.wall > 0)) {
        std::fprintf(stderr, "granrepro: LAMMPS run failed (%s in %s); input and output kept there\n",
                     argv_text(argv).c_str(), dir.c_str());
        r.time.wall = NAN;
    }
    return r;
}

struct Frame {
    long step = 0;
    std::vector<double> mass, x, y, vx, vy; // by id
};

std::vector<Frame> read_dump(const std::filesystem::path& file, std::size_t n) {
    std::vector<Frame> frames;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("ITEM: TIMESTEP", 0) == 0) {
            frames.emplace_back();
            in >> frames.back().step;
            Frame& f = frames.back();
            f.mass.assign(n, NAN), f.x.assign(n, NAN), f.y.assign(n, NAN), f.vx.assign(n, NAN), f.vy.assign(n, NAN);
        } else if (line.rfind("ITEM: ATOMS", 0) == 0 && !frames.empty()) {
            Frame& f = frames.back();
            for (std::size_t k = 0; k < n; ++k) {
                long id;
                double m, x, y, vx, vy;
                if (!(in >> id >> m >> x >> y >> vx >> vy) || id < 1 || std::size_t(id) > n) break;
                const std::size_t i = std::size_t(id - 1);
                f.mass[i] = m, f.x[i] = x, f.y[i] = y, f.vx[i] = vx, f.vy[i] = vy;
            }
        }
    }
    return frames;
}

double kinetic_energy(const std::vector<double>& m, const std::vector<double>& vx, const std::vector<double>& vy) {
    double e = 0;
    for (std::size_t i = 0; i < m.size(); ++i) e += 0.5 * m[i] * (vx[i] * vx[i] + vy[i] * vy[i]);
    return e;
}

// rms |r_a - r_b| / d_mean over the grains (minimum image along the periodic y).
double rms_dr(const PipeSpec& spec, const std::vector<double>& xa, const std::vector<double>& ya,
              const std::vector<double>& xb, const std::vector<double>& yb) {
    double sum2 = 0;
    for (std::size_t i = 0; i < xa.size(); ++i) {
        double dy = ya[i] - yb[i];
        dy -= spec.geo.length * std::round(dy / spec.geo.length);
        sum2 += (xa[i] - xb[i]) * (xa[i] - xb[i]) + dy * dy;
    }
    return std::sqrt(sum2 / double(xa.size())) / spec.d_mean;
}

// The present grains of eng, to start a copy of it.
PipeStart grains_of(const Engine& eng) { return {eng.x(), eng.y(), eng.vx(), eng.vy(), eng.radius(), eng.mass()}; }

// The same 5000 steps in both codes from the same start: kinetic energy, mean velocity and the
// grains' positions every 1000 steps; beside them, how far two granrepro runs drift apart when one
// grain starts 1e-12 m (1e-9 diameters) away, which is what chaos alone does to such a comparison.
void trajectory_check(const Lammps& l, const std::filesystem::path& dir, const PipeSpec& spec) {
    const long steps = 5000, every = 1000;
    Engine eng = build_pipe(spec);
    write_lammps_case(dir, eng, spec, steps, every);
    const LammpsRun run = run_lammps(l, dir);
    if (std::isnan(run.time.wall)) return;
    const std::size_t n = eng.size();
    const std::vector<Frame> frames = read_dump(dir / "traj.dump", n);
    const std::vector<double> mass = eng.mass();
    // The twin: the same grains, the first one displaced by 1e-12 m along x.
    PipeStart moved = grains_of(eng);
    moved.x[0] += 1e-12;
    Engine twin = pipe_engine(spec, moved, eng.normal_law(), eng.shear_law(), eng.dt());
    double mass_dev = 0;
    if (!frames.empty())
        for (std::size_t i = 0; i < n; ++i) mass_dev = std::max(mass_dev, std::abs(frames[0].mass[i] / mass[i] - 1));
    std::printf("  Trajectories: 5000 steps from the same start (LAMMPS masses = ours to %.1e); 'twin' is granrepro\n"
                "  with one grain moved by 1e-12 m at the start (chaos alone):\n", mass_dev);
    std::printf("    %6s %13s %13s %11s %11s %11s %11s %17s\n", "step", "KE ours [J]", "KE LAMMPS", "LAMMPS/ours",
                "twin/ours", "<v_y> ours", "<v_y> LAMMPS", "rms |dr| / d");
    std::printf("    %6s %13s %13s %11s %11s %11s %11s %17s\n", "", "", "", "- 1", "- 1", "[m/s]", "[m/s]", "LAMMPS    twin");
    auto dr_ours = [&](const std::vector<double>& x, const std::vector<double>& y) {
        return rms_dr(spec, eng.x(), eng.y(), x, y);
    };
    // Each code's own change when dt is halved, at the same times: the fair yardstick for the
    // comparison above. The codes evaluate the velocity-dependent forces (dashpot, Coulomb) at
    // different points of the step (LAMMPS velocity Verlet with half-step velocities, ours with
    // the step's predicted velocities), so they differ by O(dt) per contact, as each does from
    // itself at dt/2; the twin measures round-off chaos only.
    Engine half = pipe_engine(spec, grains_of(eng), eng.normal_law(), eng.shear_law(), eng.dt() / 2);
    const std::filesystem::path dir_half = dir / "half-dt";
    std::filesystem::create_directories(dir_half);
    write_lammps_case(dir_half, half, spec, 2 * steps, 2 * every);
    const LammpsRun run_half = run_lammps(l, dir_half);
    const std::vector<Frame> frames_half =
        std::isnan(run_half.time.wall) ? std::vector<Frame>{} : read_dump(dir_half / "traj.dump", n);
    struct Row { long step; double ke_us, ke_l, ke_twin, ke_half, vy_us, vy_l, dr_l, dr_twin, dr_half, dr_lhalf; };
    std::vector<Row> rows;
    for (const Frame& f : frames) {
        if (f.step == 0) continue;
        eng.advance(f.step - eng.steps());
        twin.advance(f.step - twin.steps());
        half.advance(2 * f.step - half.steps());
        Row r{f.step, kinetic_energy(mass, eng.vx(), eng.vy()), kinetic_energy(mass, f.vx, f.vy),
              kinetic_energy(mass, twin.vx(), twin.vy()), kinetic_energy(mass, half.vx(), half.vy()), 0, 0,
              dr_ours(f.x, f.y), dr_ours(twin.x(), twin.y()), dr_ours(half.x(), half.y()), NAN};
        for (std::size_t i = 0; i < n; ++i) {
            r.vy_us += eng.vy()[i] / double(n);
            r.vy_l += f.vy[i] / double(n);
        }
        // LAMMPS at dt/2 against LAMMPS at dt (both dumped at the same times).
        for (const Frame& h : frames_half)
            if (h.step == 2 * f.step) r.dr_lhalf = rms_dr(spec, f.x, f.y, h.x, h.y);
        rows.push_back(r);
    }
    for (const Row& r : rows)
        std::printf("    %6ld %13.6e %13.6e %11.2e %11.2e %11.5f %11.5f %8.1e %8.1e\n", r.step, r.ke_us, r.ke_l,
                    r.ke_l / r.ke_us - 1, r.ke_twin / r.ke_us - 1, r.vy_us, r.vy_l, r.dr_l, r.dr_twin);
    std::printf("  The yardstick: each code against itself at dt/2 (same times), rms |dr| / d and KE change:\n");
    std::printf("    %6s %17s %17s %17s\n", "step", "LAMMPS vs ours", "ours: dt/2 vs dt", "LAMMPS: dt/2 vs dt");
    for (const Row& r : rows)
        std::printf("    %6ld %17.1e %8.1e %8.1e %17.1e\n", r.step, r.dr_l, r.dr_half, r.ke_half / r.ke_us - 1, r.dr_lhalf);
    std::printf("  (LAMMPS against ours is a physics mismatch only if it is well above both dt/2 columns.)\n");
}

// ---- the comparison ------------------------------------------------------------------------

void comparison(const BenchOptions& opt) {
    const long steps = opt.steps > 0 ? opt.steps : 400000;
    const PipeSpec spec = bench_spec(0.111);
    const Engine probe = build_pipe(spec);
    const std::size_t n = probe.size();
    std::printf("bench soft: the Schäfer-Wolf Fig. 6 pipe, %zu free grains (width %.0f mm, length %.0f mm, k_N %g N/m, "
                "e_N %g, mu %g, slow start), dt = %.4g s, skin %g mm\n",
                n, spec.geo.width * 1e3, spec.geo.length * 1e3, spec.k_N, spec.e_N, spec.mu, probe.dt(), spec.skin * 1e3);
    std::printf("  Coulomb friction in the magnitude reading of Eq. (2), mu |F_N| with the dashpot (gran/hooke's cap);\n"
                "  the comparison keeps this physics whatever reading the experiments use.\n");
    std::printf("  Window: steps 0-%ld (t = 0-%.3f s) from the same start in both codes; medians of %d interleaved rounds.\n",
                steps, double(steps) * probe.dt(), opt.repeats);

    const Lammps l = find_lammps();
    const auto dir = std::filesystem::temp_directory_path() / ("granrepro-bench-soft-" + std::to_string(getpid()));
    if (l.lmp.empty()) {
        std::printf("  LAMMPS: skipped: %s\n", l.why_not.c_str());
    } else {
        std::filesystem::create_directories(dir);
        std::printf("  LAMMPS: %s (%s)\n", l.version.c_str(), l.lmp.c_str());
        trajectory_check(l, dir, spec);
        write_lammps_case(dir, probe, spec, steps, 0);
    }

    Series us1, l1; // granrepro and LAMMPS on 1 core
    long builds = 0, lmp_builds = -1;
    const double load_before = load_average();
    for (int r = 0; r < opt.repeats; ++r) {
        {
            Engine eng = build_pipe(spec);
            us1.add(time_advance(eng, steps));
            builds = eng.list_builds();
        }
        if (!l.lmp.empty()) {
            const LammpsRun lr = run_lammps(l, dir);
            l1.add(lr.time);
            lmp_builds = lr.neighbor_builds;
        }
    }
    const double load_after = load_average();
    if (!l.lmp.empty() && !std::getenv("GRANREPRO_KEEP_LAMMPS")) std::filesystem::remove_all(dir);
    else if (!l.lmp.empty()) std::printf("  LAMMPS files kept in %s\n", dir.c_str());

    const double work = double(n) * double(steps);
    auto row = [&](const char* what, const std::vector<double>& ours, const std::vector<double>& theirs) {
        const double a = work / median(ours), b = work / median(theirs);
        if (theirs.empty()) std::printf("  %-34s %12.4g %12s %8s\n", what, a, "-", "-");
        else std::printf("  %-34s %12.4g %12.4g %8.2f\n", what, a, b, a / b);
    };
    std::printf("  Load average (1 min) %.2f before, %.2f after. List builds in the window: ours %ld, LAMMPS %ld.\n",
                load_before, load_after, builds, lmp_builds);
    std::printf("  %-34s %12s %12s %8s\n", "free-grain steps per second", "granrepro", "LAMMPS", "ratio");
    row("1 core, per CPU second", us1.cpu, l1.cpu);
    row("1 core, per wall second", us1.wall, l1.wall);
}

// ---- cost against size --------------------------------------------------------------------

// Size of the level-`level` data (or unified) cache of CPU 0 from sysfs [bytes], 0 if unknown.
// (sysconf's _SC_LEVEL3_CACHE_SIZE reports 320 MiB on this VM, sysfs and lscpu 32 MiB.)
long cache_bytes(int level) {
    for (int k = 0; k < 8; ++k) {
        const std::string dir = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(k) + "/";
        std::ifstream lv(dir + "level"), ty(dir + "type"), sz(dir + "size");
        int l = 0;
        std::string type, size;
        if (!(lv >> l) || !(ty >> type) || !(sz >> size)) break;
        if (l != level || type == "Instruction") continue;
        long v = std::atol(size.c_str());
        if (size.back() == 'K') v *= 1024;
        if (size.back() == 'M') v *= 1024 * 1024;
        return v;
    }
    return 0;
}

void sizes(const BenchOptions& opt) {
    const long warm = 1000, timed = opt.steps > 0 ? opt.steps : 4000;
    std::printf("bench soft --sizes: the bench pipe (width 20 mm, k_N 2000 N/m, e_N 0.95, area fraction 0.55) at "
                "several lengths;\n  steps %ld-%ld after the slow start (repeated for small pipes to >= 0.5 s), medians "
                "of %d runs. Caches: L2 %ld KiB, L3 %ld MiB.\n",
                warm, warm + timed, opt.repeats, cache_bytes(2) / 1024, cache_bytes(3) / 1024 / 1024);
    const double load_before = load_average();
    std::printf("  %8s %8s %14s %10s %10s %10s\n", "grains", "length", "1 core", "ns/grain", "bytes/", "builds/");
    std::printf("  %8s %8s %14s %10s %10s %10s\n", "", "[m]", "[g-steps/cpu-s]", "-step", "grain", "1000 steps");
    for (const long target : {500L, 1500L, 5000L, 20000L, 100000L}) {
        // Area fraction 0.55 of (width - d_wall) x length with <d^2> = d_mean^2 (1 + p^2/3).
        const PipeSpec probe_spec = bench_spec(1.0);
        const double per_metre = probe_spec.phi * (probe_spec.geo.width - 2 * probe_spec.geo.wall_radius) /
                                 (M_PI / 4 * probe_spec.d_mean * probe_spec.d_mean *
                                  (1 + probe_spec.polydispersity * probe_spec.polydispersity / 3));
        const PipeSpec spec = bench_spec(double(target) / per_metre);
        std::vector<double> r1;
        double bytes = 0, builds = 0;
        std::size_t n = 0;
        for (int rep = 0; rep < opt.repeats; ++rep) {
            double cpu = 0, work = 0;
            while (cpu < 0.5) {
                Engine eng = build_pipe(spec);
                const Timing tm = time_window(eng, warm, timed, builds);
                cpu += tm.cpu;
                n = eng.size();
                work += double(n) * double(timed);
                bytes = eng.bytes_per_grain();
            }
            r1.push_back(work / cpu);
        }
        const double a = median(r1);
        std::printf("  %8zu %8.3f %14.4g %10.2f %10.0f %10.1f\n", n, spec.geo.length, a, 1e9 / a, bytes, builds);
    }
    std::printf("  Load average (1 min) %.2f before, %.2f after.\n", load_before, load_average());
}

// ---- cost against the flow speed -------------------------------------------------------------

// The Fig. 6 fast branch moves the grains past the fixed wall grains at 20-250 m/s, 0.02-0.2 mm
// per step against a 0.1 mm skin (issue 26 §5). The bench pipe (1498 grains) with its slow start
// shifted to a plug speed v downwards, timed over the steps after a short warm-up: grain-steps per
// CPU second and list builds per 1000 steps. Builds are triggered by motion relative to the mean
// displacement, and wall grains are found from a grain's height, so a plug should not rebuild
// more often at 200 m/s than at 1 m/s; the contacts with the wall grains change every few steps.
void speeds(const BenchOptions& opt) {
    const long warm = 200, timed = opt.steps > 0 ? opt.steps : 4000;
    const PipeSpec spec = bench_spec(0.111);
    std::printf("bench soft --speeds: the bench pipe (width 20 mm, length 111 mm, k_N 2000 N/m, e_N 0.95), its slow "
                "start moving down at v;\n  steps %ld-%ld, medians of %d runs, 1 thread.\n",
                warm, warm + timed, opt.repeats);
    const double load_before = load_average();
    std::printf("  %8s %16s %10s %12s %14s\n", "v [m/s]", "[g-steps/cpu-s]", "ns/g-step", "builds/1000", "step / skin");
    for (const double v : {1.0, 20.0, 200.0}) {
        std::vector<double> rate;
        double builds = 0, dt = 0;
        for (int rep = 0; rep < opt.repeats; ++rep) {
            const Engine start = build_pipe(spec);
            PipeStart moving = grains_of(start);
            for (double& vy : moving.vy) vy -= v;
            Engine eng = pipe_engine(spec, moving, start.normal_law(), start.shear_law(), start.dt());
            const Timing tm = time_window(eng, warm, timed, builds);
            rate.push_back(double(eng.size()) * double(timed) / tm.cpu);
            dt = eng.dt();
        }
        const double a = median(rate);
        std::printf("  %8.0f %16.4g %10.2f %12.1f %14.2f\n", v, a, 1e9 / a, builds, v * dt / spec.skin);
    }
    std::printf("  Load average (1 min) %.2f before, %.2f after.\n", load_before, load_average());
}

} // namespace

void bench_soft_report(const BenchOptions& opt) {
    if (opt.sizes) sizes(opt);
    else if (opt.speeds) speeds(opt);
    else comparison(opt);
}

} // namespace granrepro
