# Turns the `BENCH <platform> lattice/...` lines (examples/bench/lattice.rs) into the "Ray lattice"
# section of docs/benchmarks.md, next to the thesis' Table 3.2. Variables: date, load_before,
# load_after, commit, native_cmd, wasm_cmd, threads.
function s(us) { return (us >= 1e6) ? sprintf("%.2f s", us / 1e6) : sprintf("%.1f ms", us / 1000) }
function r(a, b) { return (a > 0 && b > 0) ? sprintf("%.1f×", a / b) : "–" }
function cell(p, c) { return ((p, c) in med) ? s(med[p, c]) : "not run" }
# One table row per case of the space-separated list (ids below lattice/): native, wasm, result.
function rows(list,    ids, n, i, c, res) {
  n = split(list, ids, " ")
  for (i = 1; i <= n; i++) {
    c = "lattice/" ids[i]
    res = summ[c]; gsub(";", ", ", res); gsub("=", " ", res)
    printf "| %s | %s | %s | %s |\n", ids[i], cell("native", c), cell("wasm", c), res
  }
}
$1 == "BENCH" && $3 ~ /^lattice\// { med[$2, $3] = $4; best[$2, $3] = $5; summ[$3] = $8 }
END {
  print "<!-- lattice:begin (scripts/bench.sh --lattice rewrites this section) -->"
  print "## Ray lattice (Zhang's thesis, Table 3.2)"
  print ""
  print "The thesis' constant-orientation workspace: x ∈ [0.2, 3.8], y ∈ [1.1, 2.9], z ∈ [0.3, 3.7],"
  print "identity orientation, n values per axis; case 1 cable–cable only (`cdpr7.json`), case 2 + the box"
  print "(`cdpr7-box.json`), case 3 + the tree (`cdpr7-tree.json`). \"rays\": `Lattice::build` (3n² exact rays,"
  print "the graph and its components) on one thread, and `Lattice::build_parallel` (the rays spread over"
  print "the machine's " threads " cores, as `cablenav lattice` runs them); \"points\": `point_grid` (n³ poses checked,"
  print "components by neighbours). \"× thesis\": the thesis' RBM time over ours, one thread / all cores."
  print "Median of 3 runs after one untimed run. Measured " date ", commit " commit "; load average before " load_before ", after " load_after
  print "(a shared 2-core VM: a load average above 1 means other work ran at the same time and inflated the times)."
  print ""
  print "    " native_cmd
  print "    " wasm_cmd
  print ""
  print "| n | case | rays, 1 thread | rays, " threads " threads | points, native | points / rays | rays, wasm | points, wasm | thesis RBM (MATLAB) | × thesis | thesis point-wise | result (rays) |"
  print "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
  split("87.0698 187.0063 330.3755", t1, " "); split("255.5473 575.4497 1011.9294", t2, " "); split("111.3884 248.1464 465.7290", t3, " ")
  split("89.1323 288.4506 677.2744", pw, " ")
  k = 0
  for (n = 20; n <= 40; n += 10) {
    k++
    split("case1-cables case2-box case3-tree", cs, " ")
    for (i = 1; i <= 3; i++) {
      c = cs[i]; rc = "lattice/" c "/rays-" n; pc = "lattice/" c "/points-" n; qc = "lattice/" c "/rays-parallel-" n
      thesis = (i == 1) ? t1[k] : (i == 2) ? t2[k] : t3[k]
      tp = (i == 1) ? pw[k] " s" : "–"
      res = summ[rc]; gsub(";", ", ", res); gsub("=", " ", res)
      speedup = "–"
      if ((("native", rc) in med) && (("native", qc) in med)) speedup = sprintf("%.0f× / %.0f×", thesis * 1e6 / med["native", rc], thesis * 1e6 / med["native", qc])
      printf "| %d | %s | %s | %s | %s | %s | %s | %s | %s s | %s | %s | %s |\n", n, c, cell("native", rc), cell("native", qc), cell("native", pc), r(med["native", pc], med["native", rc]), cell("wasm", rc), cell("wasm", pc), thesis, speedup, tp, res
    }
  }
  print ""
  print "\"points / rays\" above 1 means the lattice is faster than the point-wise grid at the same resolution"
  print "(the thesis found 1.0× at 20 steps and 2.0× at 40 for case 1). Here both run on the same core;"
  print "a ray is one exact computation over the whole range, a point one per-pose check."
  print ""
  print "### Lattice planning (7 values per free coordinate, `LatticeParams::default()`)"
  print ""
  print "| query | native median | wasm median | result |"
  print "|---|---:|---:|---|"
  rows("plan/tree/around-tree plan/box/over-box plan/robocrane/q1-q2")
  print ""
  print "### Multi-link robot: the thesis' 4-DoF arm (Fig. 3.12, docs/multilink.md)"
  print ""
  print "`static/multilink/bmarm-x4-2.json`: the α–β cross-section at γ = −π/12, θ = π/12 over [−π/4, π/4]²"
  print "(n values per axis; all conditions: cable–cable, cable–link, joint-space wrench closure), and the"
  print "path `across the gap` (β from −0.4 to 0.4) verified exactly and point-wise."
  print ""
  print "| case | native median | wasm median | result |"
  print "|---|---:|---:|---|"
  rows("mcdr-fig312/rays-10 mcdr-fig312/points-10 mcdr-fig312/rays-40 mcdr-fig312/points-40 mcdr-path/exact mcdr-path/pointwise-0.01 mcdr-path/pointwise-0.001")
  print ""
  printf "Exact path verification against point-wise sampling in the same run: Δt = 0.01 %s, Δt = 0.001 %s (point-wise / exact, native).\n", r(med["native", "lattice/mcdr-path/pointwise-0.01"], med["native", "lattice/mcdr-path/exact"]), r(med["native", "lattice/mcdr-path/pointwise-0.001"], med["native", "lattice/mcdr-path/exact"])
  print ""
  print "The same path with the links' weights held (CASPR's masses of BMArm_X4_2, 0.871 kg and 0.3334 kg,"
  print "and its gravity; static feasibility by linear programs, docs/multilink.md):"
  print ""
  print "| case | native median | wasm median | result |"
  print "|---|---:|---:|---|"
  rows("mcdr-weighed/exact mcdr-weighed/pointwise-0.01 mcdr-weighed/pointwise-0.001")
  print ""
  printf "Point-wise / exact with the weights, native: Δt = 0.01 %s, Δt = 0.001 %s.\n", r(med["native", "lattice/mcdr-weighed/pointwise-0.01"], med["native", "lattice/mcdr-weighed/exact"]), r(med["native", "lattice/mcdr-weighed/pointwise-0.001"], med["native", "lattice/mcdr-weighed/exact"])
  print "<!-- lattice:end -->"
}
