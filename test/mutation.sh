#!/usr/bin/env bash
# Mutation check: do the tests bite? Applies deliberate bugs, one at a time,
# to a scratch copy of the working tree, rebuilds only what the mutation
# needs and runs the tests that must catch it. A mutation is caught (killed)
# when one of its tests fails; every one must be.
#
#   bash test/mutation.sh                  # every mutation, then the kill table
#   bash test/mutation.sh 3 5              # only mutations 3 and 5 (numbers as listed)
#   bash test/mutation.sh --wing sphere    # only one wing's mutations
#   bash test/mutation.sh --list           # the mutations, numbered, and nothing else
#   bash test/mutation.sh --check          # only whether each text occurs exactly once
#   bash test/mutation.sh --sample KEY N   # N mutations picked by KEY (CI: the commit), see below
#   bash test/mutation.sh --no-baseline 53 # as the sample does, for mutations given by number
#
#   MUTATION_DIR   scratch directory (default: a new mktemp -d, removed at
#                  the end); an existing one is reused, build included
#   DLF_DATA_DIR   CGAL's data set (default: <repo>/build/data)
#   JOBS           parallel compile jobs (default 2)
#   MUTATION_TABLE write the kill table (Markdown) to this file as well
#
# Each mutation is an exact text replacement in one file (a library header,
# a source of the `dlf` tool, the Python bindings or the Python package); a
# text that does not occur exactly once is an error (the code changed:
# update the mutation), never a silent pass. Each names the tests that must
# kill it, all of them tests the CI suite (`.ci/test`) runs:
#
#   gtest FILE FILTER  the GoogleTest file test/test_FILE.cpp, built alone
#                      (-DDLF_TEST_PER_FILE=ON: target dlf_test_FILE), with
#                      --gtest_filter=FILTER
#   cli                the `dlf` tool rebuilt, then test/cli_tests.sh
#   pytest FILE [K]    the Python module rebuilt (bindings.cpp, or a copy of
#                      the package's .py), then python/tests/FILE (pytest -k K)
#
# The scratch build compiles file by file (-DDLF_UNITY_BUILD=OFF) at -O1,
# through ccache when it is installed, so that a mutation recompiles one
# translation unit and the restored file's dependents are cache hits.
# Exit 0 only when every selected mutation applied and was caught.
#
# --sample KEY N (what `.ci/mutations` runs after `.ci/test`): N mutations
# among the cheap ones, picked by a hash of KEY (the first a library one,
# the second a Python one, more spread over the library's), so that
# successive commits rotate through them. Cheap: a header
# mutation (one test file compiled, mutated, in the scratch build) or a
# mutation of the Python package's .py (no compilation: a copy of the
# package of the already built tree, SAMPLE_BUILD, default <repo>/build,
# with that tree's `dlf`). No baseline: the suite of that build has just
# passed on the unmutated tree. The tool's, the reader's and the bindings'
# mutations need the tool's 25 translation units compiled in the scratch
# build, beyond a CI budget: they run in the full table only.
set -euo pipefail
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
DATA_DIR=${DLF_DATA_DIR:-$REPO/build/data}
JOBS=${JOBS:-2}

INC=include/CGAL/Surface_mesh_parameterization
DLF=$INC/internal/discrete_lie_flow
PY=python/discrete_lie_flow
STOP_TESTS='interrupt or killed_study or second_driver'
# wing | name | file | text | replacement | tests that must kill it
MUTATIONS=(
  # --- disk: core numerics, the flow driver, the border, holes, the paper and literal modes
  "disk|critical root of the quadratic with the wrong sign|$DLF/core/critical_step.h|take(q / a);|take(-q / a);|gtest numerics Critical_step.*"
  "disk|linear term of the signed-area quadratic with a wrong sign|$DLF/core/critical_step.h|ex * hy - ey * hx + gx * fy - gy * fx|ex * hy - ey * hx - gx * fy + gy * fx|gtest numerics Critical_step.*"
  "disk|exact certification dropped (every triangle counted positive)|$DLF/core/certification.h|if(o == CGAL::POSITIVE) continue;|continue;|gtest numerics Certification.*"
  "disk|area lumping skips a corner of every face|$DLF/core/area_elements.h|for(int k = 0; k < 3; ++k) out[faces[f][k]] += value[f] / 3;|for(int k = 0; k < 2; ++k) out[faces[f][k]] += value[f] / 3;|gtest features Features.AreaElementsAreTheLumpedAreas:Features.*Area*"
  "disk|report's target areas lumped from the domain's areas instead of the targets|$DLF/flow/flow_report.h|lump_on_vertices(p.size(), out.domain_faces, out.domain_target, R.target_area);|lump_on_vertices(p.size(), out.domain_faces, u, R.target_area);|gtest disk_flow DataSet/Certified_disk.Circle/mushroom:DataSet/Free_border.Lscm/mushroom"
  "disk|plateau test the wrong way round (every run stops early)|$DLF/flow/flow_driver.h|back(m_rules.plateau_window) - x < m_rules.plateau_tolerance * (x - 1)|back(m_rules.plateau_window) - x > m_rules.plateau_tolerance * (x - 1)|gtest density DensityRegions.*"
  "disk|paper mode keeps the targets of flipped faces (no retargeting)|$DLF/disk/planar_paper_flow.h|m_target[std::size_t(f)] = m_targets(m_tri.faces[std::size_t(f)]); }|(void)f; }|gtest disk_flow DataSet/Paper_disk.Circle/mushroom"
  "disk|density ignored (targets are the surface areas)|$INC/Discrete_lie_flow_parameterizer_3.h|P.target[f] = rho * a;|P.target[f] = a;|gtest density DensityRegions.*"
  "disk|share error relative to the larger side (too lenient)|$DLF/core/density_levels.h|/ (std::min)(p, 1 - p);|/ (std::max)(p, 1 - p);|gtest density DensityRegions.*"
  "disk|circle fitted 0.01% too large (border off the circle)|$DLF/disk/boundary_curve.h|radius = r / double(pts.size());|radius = 1.0001 * r / double(pts.size());|gtest numerics Boundary_curve.*"
  "disk|inverted faces never counted in the metrics|$DLF/core/distortion.h|if(inverted) ++m.inverted_faces;|if(false) ++m.inverted_faces;|gtest numerics Distortion.*"
  "disk|holes: the fill's targets almost nil (the holes shrink to nothing)|$DLF/disk/disk_holes.h|P.target.push_back(rho * (std::max)(area, hole_fill_floor * area_g));|P.target.push_back(rho * 1e-6 * area_g);|gtest inputs Holes.*"
  "disk|holes: the fill oriented against the caller's faces|$DLF/disk/disk_holes.h|P.faces.push_back(Face{{ a, b, c }});|P.faces.push_back(Face{{ b, a, c }});|gtest inputs Holes.*"
  "disk|holes: the caller's start kept (no Tutte embedding of the filled disk)|$INC/Discrete_lie_flow_parameterizer_3.h|const std::vector<D::Vec2> given(uv);\n    if(!D::filled_disk_tutte<|const std::vector<D::Vec2> given(uv);\n    if(false \&\& !D::filled_disk_tutte<|gtest inputs Holes.*"
  "disk|holes: the report counts the fill's faces|$DLF/disk/disk_flow.h|R.faces = P.caller_faces();|R.faces = P.faces.size();|gtest inputs Holes.*"
  "disk|literal mode: the full critical step (no μ)|$DLF/flow/literal_rules.h|: step_fraction(opt, literal_default_mu) * critical;|: critical;|gtest literal Literal.*:Errata.*"
  "disk|literal mode: a folding step taken (no exact check)|$DLF/disk/planar_literal_flow.h|count_orientations_2(m_trial, m_tri.faces), out)|count_orientations_2(m_trial, std::vector<Face>()), out)|gtest literal Literal.*:Errata.*"
  # --- disk: the certified direction and energy
  "disk|certified disk flow: the exact check of a trial step skipped|$DLF/disk/planar_certified_flow.h|if(!certified_trial_2(m_trial, m_P.faces)) { ++out.rejected_by_exact_check; continue; }|if(false) { ++out.rejected_by_exact_check; continue; }|gtest features Features.RejectedByExactCheckIsCounted"
  "disk|Sobolev direction: the border moves up the gradient|$DLF/disk/sobolev_direction.h|const double s = -gs / m_diag[v];|const double s = gs / m_diag[v];|gtest numerics Sobolev_direction.*"
  "disk|Gauss-Newton: the Jacobian of a face's area with a wrong sign|$DLF/disk/planar_gauss_newton.h|l.J[i] = 0.5 * ((a[1] - b[1]) * l.e[i][0] + (b[0] - a[0]) * l.e[i][1]);|l.J[i] = 0.5 * ((a[1] - b[1]) * l.e[i][0] - (b[0] - a[0]) * l.e[i][1]);|gtest numerics Planar_gauss_newton.*"
  "disk|planar relaxation: a move's energy change with the wrong sign|$DLF/disk/planar_relaxation.h|dK += energy.weight(f) * (1 / un - 1 / u[f]);|dK += energy.weight(f) * (1 / u[f] - 1 / un);|gtest numerics Planar_relaxation.*"
  "disk|barrier energy: the gradient's second term with the wrong sign|$DLF/core/area_barrier_energy.h|dE[t] = K - U * m_c[t] / (u[t] * u[t]);|dE[t] = K + U * m_c[t] / (u[t] * u[t]);|gtest numerics Barrier_energy.*"
  "disk|border spacing: Tutte's interior system with its neighbours' sign flipped|$DLF/disk/border_spacing.h|if(interior[std::size_t(w)] >= 0) triplets.emplace_back(interior[v], interior[std::size_t(w)], -1.);|if(interior[std::size_t(w)] >= 0) triplets.emplace_back(interior[v], interior[std::size_t(w)], 1.);|gtest disk_flow DataSet/Certified_disk.*mushroom*:DataSet/Certified_disk.*nefertiti*"
  "disk|edge flips: the Delaunay test the wrong way round|$DLF/core/edge_flips.h|if(CGAL::side_of_oriented_circle(pt(a), pt(b), pt(c), pt(d)) != CGAL::ON_POSITIVE_SIDE) return true;|if(CGAL::side_of_oriented_circle(pt(a), pt(b), pt(c), pt(d)) == CGAL::ON_POSITIVE_SIDE) return true;|gtest numerics Edge_flips.*"
  # --- sphere
  "sphere|critical root: the spherical orientation cubic's λ² term with a wrong sign|$DLF/core/critical_step.h|dot(p0, eh) + dot(p0, gf) + dot(t0, ef),|dot(p0, eh) - dot(p0, gf) + dot(t0, ef),|gtest numerics Critical_step.SphereCubic*"
  "sphere|exact check: a sphere flow's trial step taken without it|$DLF/sphere/sphere_certified_flow.h|if(!certified_trial_sphere(m_trial, m_P.faces)) { ++out.rejected_by_exact_check; continue; }|if(false) { ++out.rejected_by_exact_check; continue; }|gtest features Features.RejectedByExactCheckIsCounted"
  "sphere|exact check: spherical orientation seen from the wrong side|$DLF/core/certification.h|return CGAL::orientation(P(0, 0, 0), P(a[0], a[1], a[2]), P(b[0], b[1], b[2]), P(c[0], c[1], c[2]));|return CGAL::orientation(P(0, 0, 0), P(a[0], a[1], a[2]), P(c[0], c[1], c[2]), P(b[0], b[1], b[2]));|gtest sphere Sphere_map.SphereAndEllipsoid:Sphere_initial_map.*"
  "sphere|relaxation: the cone areas' pull left out of a vertex's model|$DLF/sphere/sphere_relaxation.h|model.add(kappa * energy.derivative(Sw, f, w[f]), kappa * energy.curvature(Sw, f, w[f]), dot(e1, cone), dot(e2, cone));|model.add(0 * energy.derivative(Sw, f, w[f]), kappa * energy.curvature(Sw, f, w[f]), dot(e1, cone), dot(e2, cone));|gtest sphere Sphere_flow.OpeningSweepsLowerTheConeDArea"
  "sphere|polish energy: the weighted derivative's barrier term with the wrong sign|$DLF/core/area_barrier_energy.h|return m_alpha[t] / s.U - s.P / (s.U * s.U) + s.K - s.U * m_c[t] / (x * x);|return m_alpha[t] / s.U - s.P / (s.U * s.U) + s.K + s.U * m_c[t] / (x * x);|gtest sphere Sphere_flow.*"
  "sphere|split-vertex start: a removed vertex put back at the mirrored fraction|$DLF/sphere/sphere_split_vertices.h|p[std::size_t(s.v)] = normalized(Vec3{{ (1 - s.t) * a[0] + s.t * b[0]|p[std::size_t(s.v)] = normalized(Vec3{{ (1 - s.t) * b[0] + s.t * a[0]|gtest sphere Sphere_start.SplitVertices*:Sphere_map.*SplitVertices*"
  "sphere|the mean \\|log area ratio\\| goal dropped from the verdict|$DLF/sphere/sphere_map.h|goals.mean_log_goal = opt.sphere.log_area_tolerance;|goals.mean_log_goal = -1;|gtest features Features.*Message*:Features.*Goal*"
  # --- volume
  "volume|tet cubic root: the cubic's λ² coefficient with a wrong sign|$DLF/volume/volume_geometry.h|det(a1, b2, b3) + det(b1, a2, b3) + det(b1, b2, a3),|det(a1, b2, b3) + det(b1, a2, b3) - det(b1, b2, a3),|gtest volume Volume.CriticalStepOfATetMatchesBisectionOnTheExactPredicate"
  "volume|exact orient3d check: an inverted input tet accepted|$DLF/volume/volume_mesh.h|if(o == NEGATIVE) {|if(o == NEGATIVE \&\& false) {|gtest volume Volume.InputsThatAreNotBallsOrNotValidAreRefused"
  "volume|exact orient3d check: every tet counted positive|$DLF/volume/volume_mesh.h|if(o == POSITIVE) continue;\n    if(o == NEGATIVE) ++c.negative;|continue;\n    if(o == NEGATIVE) ++c.negative;|gtest volume Volume.Untangling*"
  "volume|untangling acceptance: no step of the untangling ever accepted (Armijo refuses all)|$DLF/volume/volume_untangle.h|if(E_new <= m_E + 1e-4 * step * slope) return true;|if(E_new <= m_E + 1e-4 * step * slope \&\& false) return true;|gtest volume Volume.Untangling*"
  "volume|coarse level: an aggregate pair's block from one aggregate's gradients|$DLF/volume/volume_coarse_level.h|B[3 * c + d] += w[t] * h[i][c] * h[l][d];|B[3 * c + d] += w[t] * h[i][c] * h[i][d];|gtest volume Volume.CoarseMatrixIsTheGaussNewtonMatrixOnTheAggregates"
  # --- the reader (tools/dlf/mesh_input.cpp)
  "reader|a face using its first vertex twice (as its third) accepted|tools/dlf/mesh_input.cpp|if(p[0] == p[1] \|\| p[1] == p[2] \|\| p[2] == p[0])|if(p[0] == p[1] \|\| p[1] == p[2])|cli"
  "reader|an OFF face index equal to the vertex count accepted|tools/dlf/mesh_input.cpp|if(!(i >= 0 \&\& i < double(nv)) \|\| i != std::floor(i)) return false;|if(!(i >= 0 \&\& i <= double(nv)) \|\| i != std::floor(i)) return false;|cli"
  "reader|the header's counts not checked against the file's size|tools/dlf/mesh_input.cpp|check_counts(path, nv, nf, 6. * double(nv) + 2. * double(nf));|check_counts(path, nv, nf, 0.);|cli"
  "reader|vertices of no face accepted|tools/dlf/mesh_input.cpp|if(unused == 0) return;|return;|cli"
  # --- the tool: exit codes, output writing
  "tool|a run short of its targets exits 0 (no warning)|tools/dlf/verdict.h|if(R.converged()) return EXIT_OK;|return EXIT_OK;|cli"
  "tool|dlf volume short of its tolerance exits 0 (no warning)|tools/dlf/volume_command.cpp|if(R.converged()) return EXIT_OK;|return EXIT_OK;|cli"
  "tool|every error exits 1 (a flow error's 2 lost)|tools/dlf/main.cpp|return e.code();|return EXIT_BAD_INPUT;|cli"
  "tool|outputs never committed (the temporaries are thrown away)|tools/dlf/output_files.cpp|if(!f.written) continue;\n    if(std::rename(|if(true) continue;\n    if(std::rename(|cli"
  # --- Python: the bindings and the package
  "python|F of floats accepted (no TypeError)|python/bindings.cpp|if(!is_integer_kind(dtype_kind(a))) type_error(\"F must hold integers, got dtype \" + dtype_name(a));|if(false) type_error(\"F must hold integers, got dtype \" + dtype_name(a));|pytest test_module.py"
  "python|a face index equal to the vertex count accepted|python/bindings.cpp|if(i < 0 \|\| (unsigned long long)(i) >= vertices)|if(i < 0 \|\| (unsigned long long)(i) > vertices)|pytest test_module.py"
  "python|F of any width accepted|python/bindings.cpp|if(a.ndim() != 2 \|\| a.shape(1) != 3) value_error(\"F must have shape (m, 3), got \" + shape_text(a));|if(a.ndim() != 2) value_error(\"F must have shape (m, 3), got \" + shape_text(a));|pytest test_module.py"
  "python|a map short of its targets not reported (no warning, no FlowError)|$PY/__init__.py|if report.get(\"status\") == \"not_converged\":|if report.get(\"status\") == \"converged\":|pytest test_module.py"
  "python|the warning of a map short of its targets not issued|$PY/__init__.py|_warnings.warn(message, UserWarning, stacklevel=3)|pass|pytest test_module.py"
  # --- dlf-study: resume
  "study|resume forgets the rows already in the database|$PY/study.py|done = done_keys(db)\n|done = set()\n|pytest test_study.py $STOP_TESTS"
  "study|a second driver on one database not refused|$PY/study.py|fcntl.flock(f, fcntl.LOCK_EX \| fcntl.LOCK_NB)|fcntl.flock(f, fcntl.LOCK_SH \| fcntl.LOCK_NB)|pytest test_study.py $STOP_TESTS"
  "study|resume drops one of the runs still to do|$PY/study.py|todo = [(key, path, c) for key, path, c in runs if (key, c) not in done]|todo = [(key, path, c) for key, path, c in runs if (key, c) not in done][1:]|pytest test_study.py $STOP_TESTS"
  # --- added later (numbers stay: new mutations go at the end)
  "volume|a run short of its goals: the D_vol it missed left out of the message|$INC/internal/discrete_lie_flow/volume/volume_run.h|if(!(d_vol_reached - 2 <= O.tolerance)) missed << \"D_vol \" << d_vol_reached << \" > \" << 2 + O.tolerance;|(void)d_vol_reached;|gtest volume Volume.NotConvergedMessageNamesTheMissedGoals"
  "python|an atlas short of its goals warned without the report's message (the missed goal)|$PY/__init__.py|message = f\"{name}: did not converge: {report['message']}\"|message = f\"{name}: did not converge\"|pytest test_module.py atlas"
  "disk|floating border slides on its outline instead|$DLF/disk/planar_dofs.h|if(curve.kind() == Discrete_lie_flow_border::FLOATING) {|if(false) {|gtest drop_in DropIn.LscmStartKeptOnLionSeams"
  "disk|holes: a hole no point sees whole is never triangulated|$DLF/disk/loop_triangulation.h|  if(!T.add_loop(uv, loop)) return false;|  return false;|gtest drop_in DropIn.HoleNotStarShapedKeepsTheStart"
  "disk|coarse to fine: a put-back vertex's kernel clipped at the wrong point of an edge|$DLF/flow/coarse_to_fine_levels.h|const double t = s0 / (s0 - s1);|const double t = s1 / (s0 - s1);|gtest numerics Kernel_centroid.*"
  "disk|coarse to fine: a finer level's sweeps move the fixed border vertices too|$DLF/flow/coarse_to_fine_levels.h|keep[v] = movable[v] && around.first[v + 1] > around.first[v];|keep[v] = around.first[v + 1] > around.first[v];|gtest disk_flow Coarse_to_fine.*"
)

field() { # field I K: the K-th field (1-based) of mutation I
  local IFS='|'; local -a f; read -r -a f <<< "$(sed 's/\\|/\x01/g' <<< "${MUTATIONS[$(($1 - 1))]}")"
  sed 's/\x01/|/g' <<< "${f[$(($2 - 1))]}"
}
unescape() { printf '%b' "$(sed 's/\\&/\&/g' <<< "$1")"; }

selected=()
wing=""
sample=0
while (($#)); do
  case $1 in
    --list) for i in $(seq 1 ${#MUTATIONS[@]}); do printf '%2d %-7s %s\n' "$i" "$(field $i 1)" "$(field $i 2)"; done; exit 0 ;;
    --wing) wing=$2; shift ;;
    --check)
      bad=0
      for i in $(seq 1 ${#MUTATIONS[@]}); do
        n=$(FROM=$(unescape "$(field $i 4)") perl -0777 -ne '$n = () = /\Q$ENV{FROM}\E/g; print $n' "$REPO/$(field $i 3)")
        [[ "$n" == 1 ]] || { echo "mutation $i: the text occurs $n times in $(field $i 3)"; bad=1; }
      done
      exit $bad ;;
    --sample)
      sample=1
      # the library's (G) and the Python package's (P): the first pick is
      # one of G, the second one of P, more are spread over G
      G=() P=()
      for i in $(seq 1 ${#MUTATIONS[@]}); do
        r=$(field $i 6) f=$(field $i 3)
        [[ "$r" == gtest* ]] && G+=("$i")
        [[ "$r" == pytest* && "$f" == *.py ]] && P+=("$i")
      done
      h=$(( 16#$(printf '%s' "$2" | sha1sum | cut -c1-7) ))
      for ((k = 0; k < $3; ++k)); do
        if ((k == 1)); then selected+=("${P[$(( h % ${#P[@]} ))]}")
        else selected+=("${G[$(( (h + k * (${#G[@]} / $3 + 1)) % ${#G[@]} ))]}"); fi
      done
      shift 2 ;;
    --no-baseline) sample=1 ;; # as --sample, for the mutations given by number
    *) selected+=("$1") ;;
  esac
  shift
done
SAMPLE_BUILD=${SAMPLE_BUILD:-$REPO/build}
if ((${#selected[@]} == 0)); then
  for i in $(seq 1 ${#MUTATIONS[@]}); do [[ -z "$wing" || "$(field $i 1)" == "$wing" ]] && selected+=("$i"); done
fi
[[ -d "$DATA_DIR/meshes" ]] || { echo "mutation: no meshes in $DATA_DIR/meshes (run .ci/install-deps)" >&2; exit 1; }

start=$(date +%s)
if [[ -n "${MUTATION_DIR:-}" ]]; then
  SCRATCH=$MUTATION_DIR; mkdir -p "$SCRATCH"
else
  SCRATCH=$(mktemp -d "${TMPDIR:-/tmp}/dlf_mutation.XXXXXX")
  trap 'rm -rf "$SCRATCH"' EXIT
fi
SRC=$SCRATCH/src BUILD=$SCRATCH/build

# The working tree as it is (committed or not), without build outputs; an
# existing copy is refreshed only where files differ (keeps the timestamps
# of the others, so a reused build recompiles nothing it need not).
mkdir -p "$SRC"
(cd "$REPO" && git ls-files -co --exclude-standard -z | grep -zv '^build' | xargs -0 tar -cf -) > "$SCRATCH/tree.tar"
mkdir -p "$SCRATCH/fresh"; rm -rf "$SCRATCH/fresh"/*; tar -xf "$SCRATCH/tree.tar" -C "$SCRATCH/fresh"
(cd "$SCRATCH/fresh" && find . -type f) | while read -r f; do
  cmp -s "$SCRATCH/fresh/$f" "$SRC/$f" 2> /dev/null || { mkdir -p "$(dirname "$SRC/$f")"; cp "$SCRATCH/fresh/$f" "$SRC/$f"; }
done
rm -rf "$SCRATCH/fresh" "$SCRATCH/tree.tar"

needs_build=1
if ((sample)); then
  needs_build=0
  for i in "${selected[@]}"; do [[ "$(field $i 3)" == *.py ]] || needs_build=1; done
  if ((!needs_build)) && [[ ! -x "$SAMPLE_BUILD/tools/dlf" || ! -d "$SAMPLE_BUILD/python/discrete_lie_flow" ]]; then
    echo "mutation: --sample needs a built tree in $SAMPLE_BUILD (dlf and the Python module)"; exit 1
  fi
fi
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# Ninja builds several single-file targets side by side (make: one at a time).
if command -v ninja > /dev/null && [[ ! -f "$BUILD/Makefile" ]]; then launcher+=(-G Ninja); fi
# -O1: a rebuild per mutation, so compile time matters more than run time.
# No `dlf tetrahedralize` (CGAL's Mesh_3: minutes of compilation); the CLI
# test's volume checks then start from the sphere kept in test/data.
if ((needs_build)); then
  cmake -S "$SRC" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" "${launcher[@]}" \
    -DDLF_DATA_DIR="$DATA_DIR" -DDLF_BUILD_BENCHMARK=OFF -DDLF_UNITY_BUILD=OFF -DDLF_TEST_PER_FILE=ON \
    -DDLF_WITH_TETRAHEDRALIZE=OFF -DDLF_TEST_CGAL_EXAMPLES=OFF > "$SCRATCH/configure.log" 2>&1 ||
    { echo "mutation: the scratch tree does not configure:"; tail -n 20 "$SCRATCH/configure.log"; exit 1; }
fi

# target_of KIND ARGS: the build target a runner needs
target_of() {
  case $1 in
    gtest) echo "dlf_test_$2" ;;
    cli) echo dlf ;;
    pytest) echo dlf_python dlf ;; # the tests run the tool too
  esac
}
# run_tests LOG KIND ARGS...: runs the tests; prints what failed (empty: all passed)
run_tests() {
  local log=$1 kind=$2; shift 2
  local env=(OMP_THREAD_LIMIT=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1)
  case $kind in
    gtest)
      (cd "$BUILD/test" && env "${env[@]}" "./dlf_test_$1" --gtest_filter="$2" > "$log" 2>&1) || true
      if ! grep -q '^\[==========\] [1-9][0-9]* tests\? from' "$log"; then echo "(no test matched $2)"; return; fi
      sed -n 's/^\[  FAILED  \] \([A-Za-z_][^ ,]*\).*/\1/p' "$log" | sort -u | tr '\n' ' '
      grep -q '^\[  PASSED  \]' "$log" || echo "(crashed)" ;;
    cli)
      env "${env[@]}" DLF_TETRAHEDRALIZE=0 bash "$SRC/test/cli_tests.sh" "$BUILD/tools/dlf" "$DATA_DIR/meshes" > "$log" 2>&1 || true
      local n; n=$(grep -c '^FAIL' "$log" || true)
      if ((n > 0)); then echo "cli ($n checks, first: $(grep -m1 '^FAIL' "$log" | cut -c7-90))"
      elif ! grep -q '^all [0-9]* checks passed' "$log"; then echo "cli (did not finish)"; fi ;;
    pytest)
      local k=()
      (($# > 1)) && k=(-k "${*:2}")
      (cd "$SCRATCH" && env "${env[@]}" PYTHONPATH="$PY_PATH" DLF_EXECUTABLE="$DLF_EXE" DLF_DATA_DIR="$DATA_DIR" \
        PYTHONDONTWRITEBYTECODE=1 "$PYTHON" -m pytest -q -p no:cacheprovider "$SRC/python/tests/$1" "${k[@]}" > "$log" 2>&1) || true
      if grep -qE '^[0-9]+ passed' "$log" && ! grep -qE '[0-9]+ (failed|error)' "$log"; then return; fi
      local failed; failed=$(sed -n 's/^FAILED [^:]*::\([A-Za-z0-9_]*\).*/\1/p' "$log" | sort -u | tr '\n' ' ')
      echo "${failed:-pytest ($(tail -n 1 "$log"))}" ;;
  esac
}
build() { cmake --build "$BUILD" --target $1 -j"$JOBS" > "$2" 2>&1; } # $1: one or more targets
PY_PATH=$BUILD/python DLF_EXE=$BUILD/tools/dlf
# The interpreter the module was built for (as the suite's python tests).
python_of() { [[ -f "$1/CMakeCache.txt" ]] && sed -n 's/^_Python_EXECUTABLE:INTERNAL=//p' "$1/CMakeCache.txt" | head -n 1 || true; }
PYTHON=$(python_of "$BUILD")
((sample)) && PYTHON=$(python_of "$SAMPLE_BUILD")
PYTHON=${PYTHON:-python3}
if ((sample)); then # the package of the built tree, copied: its .py mutated there
  rm -rf "$SCRATCH/pkg"; mkdir -p "$SCRATCH/pkg"
  cp -r "$SAMPLE_BUILD/python/discrete_lie_flow" "$SCRATCH/pkg/"
  PY_PATH=$SCRATCH/pkg DLF_EXE=$SAMPLE_BUILD/tools/dlf
fi
runner_of() { IFS=' ' read -r -a R <<< "$(field "$1" 6)"; }

# The baseline, as the mutations come: a target is built unmutated before
# a test set runs on it for the first time (the mutated files are restored
# by then: an incremental build, ccache hits), and each test set must pass
# there; the mutations of a test set that fails unmutated are errors. So
# the kill table grows mutation by mutation, in the order given.
declare -A baseline_done=()
for i in "${selected[@]}"; do
  ((i >= 1 && i <= ${#MUTATIONS[@]})) || { echo "mutation: no mutation $i (1 to ${#MUTATIONS[@]})"; exit 1; }
done
if ((sample)); then
  echo "mutation: scratch $SCRATCH; sample of ${#selected[@]}: ${selected[*]} (no baseline: the suite of $SAMPLE_BUILD passed)"
  for i in "${selected[@]}"; do runner_of "$i"; baseline_done[${R[*]}]=ok; done
else
  echo "mutation: scratch $SCRATCH; ${#selected[@]} mutations: ${selected[*]}"
fi
baseline() { # baseline I: the unmutated target and test set of mutation I
  local key="${R[*]}" t; t=$(target_of "${R[@]}")
  [[ -n "${baseline_done[$key]:-}" ]] && return
  if ! build "$t" "$SCRATCH/baseline_$1.build"; then
    echo "mutation: the unmutated tree does not build $t (see $SCRATCH/baseline_$1.build)"; exit 1
  fi
  local failed; failed=$(run_tests "$SCRATCH/baseline_$1.run" "${R[@]}")
  baseline_done[$key]=ok
  if [[ -n "$failed" ]]; then
    echo "mutation: the unmutated tree fails '$key': $failed (see $SCRATCH/baseline_$1.run); its mutations are errors"
    baseline_done[$key]=failed
  fi
}

caught=0 missed=0 errors=0
rows=()
for i in "${selected[@]}"; do
  w=$(field "$i" 1) name=$(field "$i" 2) file=$(field "$i" 3)
  from=$(unescape "$(field "$i" 4)") to=$(unescape "$(field "$i" 5)")
  runner_of "$i"; target=$(target_of "${R[@]}")
  baseline "$i"
  t0=$(date +%s)
  if [[ "${baseline_done[${R[*]}]}" != ok ]]; then
    printf 'mutation %d: ERROR  %s: its tests fail unmutated\n' "$i" "$name"
    errors=$((errors + 1)); rows+=("| $i | $w | ${name//|/\\|} | \`${file#$DLF/}\` | **error: tests fail unmutated** | |"); continue
  fi
  target_file=$SRC/$file
  ((sample)) && [[ "$file" == *.py ]] && target_file=$SCRATCH/pkg/discrete_lie_flow/$(basename "$file")
  cp "$target_file" "$SCRATCH/original"
  if ! FROM=$from TO=$to perl -0777 -i -pe '$n = () = /\Q$ENV{FROM}\E/g; s/\Q$ENV{FROM}\E/$ENV{TO}/; END { exit($n == 1 ? 0 : 3) }' "$target_file"; then
    printf 'mutation %d: ERROR  %s: the text does not occur exactly once in %s\n' "$i" "$name" "$file"
    cp "$SCRATCH/original" "$target_file"
    errors=$((errors + 1)); rows+=("| $i | $w | ${name//|/\\|} | \`${file#$DLF/}\` | **error: text not found** | |"); continue
  fi
  log=$SCRATCH/mutation_$i
  verdict=""
  failed=""
  if ((sample)) && [[ "$file" == *.py ]]; then
    echo "(nothing to build: the copied package is the one run)" > "$log.build"
  elif ! build "$target" "$log.build"; then
    printf 'mutation %d: ERROR  %s: does not compile (%s.build)\n' "$i" "$name" "$log"
    errors=$((errors + 1)); verdict="**error: does not compile**"
  elif [[ "$file" != *.py ]] && ! grep -qE 'Building CXX object|Linking' "$log.build"; then # (Ninja and make alike)
    printf 'mutation %d: ERROR  %s: nothing was recompiled (%s.build)\n' "$i" "$name" "$log"
    errors=$((errors + 1)); verdict="**error: nothing recompiled**"
  fi
  if [[ -z "$verdict" ]]; then
    failed=$(run_tests "$log.run" "${R[@]}")
    if [[ -n "$failed" ]]; then
      caught=$((caught + 1)); verdict="killed"
      printf 'mutation %d: killed %s (%d s) by %s\n' "$i" "$name" "$(( $(date +%s) - t0 ))" "$failed"
    else
      missed=$((missed + 1)); verdict="**survived**"
      printf 'mutation %d: SURVIVED %s (%d s)\n' "$i" "$name" "$(( $(date +%s) - t0 ))"
    fi
  fi
  rows+=("| $i | $w | ${name//|/\\|} | \`${file#$DLF/}\` | $verdict ($(( $(date +%s) - t0 )) s) | ${failed:-} |")
  printf '%s\n' "${rows[-1]}" >> "$SCRATCH/rows.md" # the table so far, should the run be cut short
  cp "$SCRATCH/original" "$target_file"
done
applied=$((caught + missed))
{
  echo
  echo "| # | wing | mutation | file | verdict (time) | killed by |"
  echo "|---:|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
} | tee "${MUTATION_TABLE:-/dev/null}"
echo "mutation: $caught of $applied killed (kill rate $(awk -v c=$caught -v n=$applied 'BEGIN { printf "%.0f%%", n ? 100 * c / n : 0 }')), $missed survived, $errors errors; $(( $(date +%s) - start )) s"
((missed == 0 && errors == 0))
