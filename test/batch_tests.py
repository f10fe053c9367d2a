#!/usr/bin/env python3
# Tests of `spectralseg batch` and `batch-merge`, run by CTest as a user runs
# them (the standard library; PyYAML and the Kubernetes client for the
# schema check). One group per CTest test:
#   shards  - a batch of several meshes, one garbage and one empty, as 3 shards
#             plus a merge equals the unsharded run (labels, summary without
#             its timing column); same basenames in two folders; usage errors
#   jobs    - --jobs 2 (1 thread per mesh) equals --jobs 1 (2 threads)
#   resume  - a batch killed with SIGKILL halfway (while it segments a large
#             mesh) is finished by a rerun that does
#             not touch the finished meshes; stale, changed and corrupted
#             outputs are redone; --timeout stops a mesh that hangs
#   scripts - scripts/batch: the Slurm array (with a stand-in sbatch that runs
#             the tasks here), the Kubernetes job's shell (run here per index)
#             and GNU parallel give the unsharded result; the Kubernetes files
#             pass the API's schema
#   slurm   - the Slurm array submitted to a real single-node cluster
#             (munged, slurmctld and slurmd started here): the unsharded
#             result, the merge after the array; a task cancelled halfway,
#             resubmitted, redoes only what was not finished
# usage: batch_tests.py GROUP SPECTRALSEG DATA WORK REPO
import csv
import json
import math
import os
import re
import shutil
import signal
import stat
import subprocess
import sys
import time

GROUP = sys.argv[1]
TOOL, DATA, WORK, REPO = (os.path.abspath(a) for a in sys.argv[2:6])
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL: " + message, flush=True)
    return condition


def run(args, expect_rc=None, env=None, **kwargs):
    p = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env, timeout=300,
                       cwd=WORK, **kwargs)
    shown = " ".join(str(a) for a in args).replace("\n", " ")
    shown = shown if len(shown) < 200 else shown[:200] + "..."
    if expect_rc is not None and not check(p.returncode == expect_rc,
                                           "%s: exit code %d, expected %d\n  stdout: %s\n  stderr: %s"
                                           % (shown, p.returncode, expect_rc, p.stdout, p.stderr)):
        return p
    print("ok: %s (exit %d)" % (shown, p.returncode), flush=True)
    return p


def batch(*args, expect_rc=None):
    return run([TOOL, "batch"] + [str(a) for a in args], expect_rc)


def torus(path, big_r, small_r, nu, nv, obj=False):
    """A closed torus of 2*nu*nv triangles, as OFF or OBJ."""
    vertices = []
    for i in range(nu):
        for j in range(nv):
            u, v = 2 * math.pi * i / nu, 2 * math.pi * j / nv
            vertices.append(((big_r + small_r * math.cos(v)) * math.cos(u),
                             (big_r + small_r * math.cos(v)) * math.sin(u), small_r * math.sin(v)))
    faces = []
    for i in range(nu):
        for j in range(nv):
            a, b = i * nv + j, ((i + 1) % nu) * nv + j
            c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
            faces += [(a, b, c), (a, c, d)]
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        if obj:
            f.writelines("v %.9g %.9g %.9g\n" % p for p in vertices)
            f.writelines("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in faces)
        else:
            f.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
            f.writelines("%.9g %.9g %.9g\n" % p for p in vertices)
            f.writelines("3 %d %d %d\n" % t for t in faces)


def rows(folder, stem="summary"):
    with open(os.path.join(WORK, folder, stem + ".jsonl")) as f:
        return [json.loads(line) for line in f if line.strip()]


def without_timing(table):
    return [{k: v for k, v in r.items() if k != "seconds"} for r in table]


def csv_without_timing(folder):
    with open(os.path.join(WORK, folder, "summary.csv"), newline="") as f:
        table = list(csv.reader(f))
    column = table[0].index("seconds")
    return [r[:column] + r[column + 1:] for r in table]


def label_files(folder):
    out = {}
    root = os.path.join(WORK, folder)
    for base, _, files in os.walk(root):
        for name in files:
            if name.endswith(".seg"):
                with open(os.path.join(base, name), "rb") as f:
                    out[os.path.relpath(os.path.join(base, name), root)] = f.read()
    return out


def same_result(folder, reference, what):
    check(without_timing(rows(folder)) == without_timing(rows(reference)),
          "%s: summary.jsonl differs from the unsharded run's (timings left out)" % what)
    check(csv_without_timing(folder) == csv_without_timing(reference),
          "%s: summary.csv differs from the unsharded run's (timings left out)" % what)
    labels, expected = label_files(folder), label_files(reference)
    check(sorted(labels) == sorted(expected), "%s: label files %s, expected %s" % (what, sorted(labels), sorted(expected)))
    check(labels == expected, "%s: the label files differ from the unsharded run's" % what)


def make_dataset():
    """in/: 6 meshes (two named m.off in different folders, an OBJ, one in a
    subfolder of a subfolder, a garbage file and an empty file), plus a text
    file and a hidden mesh that are not taken."""
    shutil.rmtree(os.path.join(WORK, "in"), ignore_errors=True)
    shutil.copy(os.path.join(DATA, "elephant.off"), os.path.join(WORK, "x_m.off"))
    os.makedirs(os.path.join(WORK, "in", "x"))
    shutil.move(os.path.join(WORK, "x_m.off"), os.path.join(WORK, "in", "x", "m.off"))
    torus(os.path.join(WORK, "in", "y", "m.off"), 2.0, 0.5, 12, 8)
    torus(os.path.join(WORK, "in", "t.obj"), 3.0, 1.0, 10, 6, obj=True)
    torus(os.path.join(WORK, "in", "sub", "deeper", "u.off"), 2.0, 0.8, 9, 7)
    with open(os.path.join(WORK, "in", "bad.off"), "w") as f:
        f.write("this is not a mesh\n")
    open(os.path.join(WORK, "in", "empty.off"), "w").close()
    open(os.path.join(WORK, "in", "notes.txt"), "w").close()
    torus(os.path.join(WORK, "in", ".hidden.off"), 2.0, 0.5, 5, 5)


DATASET = ["bad.off", "empty.off", "sub/deeper/u.off", "t.obj", "x/m.off", "y/m.off"]
METHOD = ["--k", "3"]


def full_run():
    shutil.rmtree(os.path.join(WORK, "full"), ignore_errors=True)
    p = batch("in", "-r", "--out", "full", *METHOD, expect_rc=1)
    check("failed: 2\n" in p.stdout, "full run: stdout should count 2 failed meshes: " + p.stdout)
    return rows("full")


def test_shards():
    make_dataset()
    table = full_run()
    check([r["mesh"] for r in table] == DATASET, "meshes found: %s, expected %s" % ([r["mesh"] for r in table], DATASET))
    status = {r["mesh"]: r for r in table}
    for name in DATASET:
        ok = name not in ("bad.off", "empty.off")
        r = status.get(name, {})
        check(r.get("status") == ("ok" if ok else "error"), "%s: status %s" % (name, r.get("status")))
        if ok:
            check(r["segments"] is not None and r["segments"] >= 2 and r["faces"] > 0 and r["labels"] == name + ".seg"
                  and os.path.exists(os.path.join(WORK, "full", name + ".json")), "%s: row %s" % (name, r))
        else:
            check(r["error"] != "" and r["labels"] == "" and not os.path.exists(os.path.join(WORK, "full", name + ".seg")),
                  "%s: row %s" % (name, r))
    check("line 1" in status["bad.off"]["error"], "bad.off: error should name the line: " + status["bad.off"]["error"])
    # the two m.off have outputs of their own
    a, b = (open(os.path.join(WORK, "full", d, "m.off.seg")).read() for d in ("x", "y"))
    check(len(a.split()) == 5558 and len(b.split()) == 192, "x/m.off.seg and y/m.off.seg: one label per face each")

    shutil.rmtree(os.path.join(WORK, "sharded"), ignore_errors=True)
    shard_of = {name: i % 3 for i, name in enumerate(DATASET)}
    for s in range(3):
        fails = any(shard_of[n] == s for n in ("bad.off", "empty.off"))
        batch("in", "-r", "--out", "sharded", *METHOD, "--shard", "%d/3" % s, expect_rc=1 if fails else 0)
        mine = [r["mesh"] for r in rows("sharded", "summary-shard-%d-of-3" % s)]
        check(mine == [n for n in DATASET if shard_of[n] == s], "shard %d/3 took %s" % (s, mine))
        if s == 1:
            p = run([TOOL, "batch-merge", "sharded"], expect_rc=1)
            check("shards 2 of 3 are missing" in p.stderr, "merge with a missing shard: " + p.stderr)
            check(not os.path.exists(os.path.join(WORK, "sharded", "summary.csv")), "merge wrote a partial summary")
    p = run([TOOL, "batch-merge", "sharded"], expect_rc=1)  # 1: two meshes failed
    check("meshes: 6\nok: 4\nskipped: 0\nfailed: 2\n" in p.stdout, "merge counts: " + p.stdout)
    same_result("sharded", "full", "3 shards merged")

    # not recursive: the top folder only
    shutil.rmtree(os.path.join(WORK, "flat"), ignore_errors=True)
    batch("in", "--out", "flat", *METHOD, expect_rc=1)
    check([r["mesh"] for r in rows("flat")] == ["bad.off", "empty.off", "t.obj"], "without -r: %s" % rows("flat"))
    # a list file (names relative to the folder of the meshes) and --png, --colored-mesh
    with open(os.path.join(WORK, "list.txt"), "w") as f:
        f.write("# meshes\nin/y/m.off\n\n  in/t.obj  \nin/y/m.off\n")
    shutil.rmtree(os.path.join(WORK, "listed"), ignore_errors=True)
    batch("--list", "list.txt", "--out", "listed", *METHOD, "--png", "--colored-mesh", "ply", expect_rc=0)
    table = rows("listed")
    check([r["mesh"] for r in table] == ["t.obj", "y/m.off"], "--list: %s" % table)
    for r in table:
        check(r["png"] == r["mesh"] + ".png" and r["colored_mesh"] == r["mesh"] + ".ply" and
              os.path.getsize(os.path.join(WORK, "listed", r["png"])) > 0 and
              os.path.getsize(os.path.join(WORK, "listed", r["colored_mesh"])) > 0, "--png --colored-mesh: %s" % r)

    # usage errors (2) and inputs that do not exist (1), before any work
    for args, rc, message in [
            (["in", "--out", "u", "--k", "3", "--shard", "3/3"], 2, "--shard must be I/N"),
            (["in", "--out", "u", "--k", "3", "--shard", "1"], 2, "--shard must be I/N"),
            (["--out", "u", "--k", "3"], 2, "no mesh given"),
            (["in", "--out", "u", "--k", "0"], 2, "--k must be a positive integer"),
            (["in", "--out", "u", "--k", "3", "--jobs", "0"], 2, "--jobs"),
            (["in", "--k", "3"], 2, "--out is required"),
            (["in", "--out", "in", "--k", "3"], 2, "also an input folder"),
            (["in/t.obj", "--out", "u", "--k", "3", "--root", "in/y"], 2, "not inside the --root"),
            (["missing_folder", "--out", "u", "--k", "3"], 1, "cannot open 'missing_folder'")]:
        p = batch(*args, expect_rc=rc)
        check(message in p.stderr, "batch %s: stderr should say '%s': %s" % (" ".join(args), message, p.stderr))
    p = run([TOOL, "batch-merge", "flat"], expect_rc=1)
    check("no shard" in p.stderr, "batch-merge of an unsharded folder: " + p.stderr)


def test_jobs():
    make_dataset()
    full_run()
    shutil.rmtree(os.path.join(WORK, "jobs2"), ignore_errors=True)
    batch("in", "-r", "--out", "jobs2", *METHOD, "--jobs", "2", "--threads", "2", expect_rc=1)
    with open(os.path.join(WORK, "jobs2", "batch.json")) as f:
        check(json.load(f)["threads_per_mesh"] == 1, "--jobs 2 --threads 2: 1 thread per mesh")
    same_result("jobs2", "full", "--jobs 2")


def stamp(path):
    s = os.stat(os.path.join(WORK, path))
    return (s.st_ino, s.st_mtime_ns)


def test_resume():
    folder = os.path.join(WORK, "k")
    shutil.rmtree(folder, ignore_errors=True)
    torus(os.path.join(folder, "a.off"), 2.0, 0.5, 12, 8)
    torus(os.path.join(folder, "b.off"), 2.0, 0.7, 10, 8)
    # a large c.off: the batch spends a second or more on it, a window in which it is killed
    # halfway (the readers refuse FIFOs, which used to block it at a known point)
    torus(os.path.join(folder, "c.off"), 2.0, 0.5, 400, 150)
    torus(os.path.join(folder, "d.off"), 3.0, 0.6, 11, 7)
    out = os.path.join(WORK, "kout")
    shutil.rmtree(out, ignore_errors=True)
    args = [TOOL, "batch", "k/a.off", "k/b.off", "k/c.off", "k/d.off", "--out", "kout", "--k", "3"]
    p = subprocess.Popen(args, cwd=WORK, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    # c.off is taken up once a and b are written (--jobs 1, sorted order)
    deadline = time.time() + 60
    def b_finished():
        try:
            with open(os.path.join(out, "b.off.json")) as f:
                return "batch" in json.load(f) and os.path.exists(os.path.join(out, "b.off.seg"))
        except (OSError, ValueError):
            return False

    while time.time() < deadline and p.poll() is None and not b_finished():
        time.sleep(0.01)
    check(p.poll() is None, "the batch ended before c.off was killed halfway")
    p.send_signal(signal.SIGKILL)  # c.off is being segmented: killed halfway
    p.wait()

    def processes_of_c():
        found = []
        for pid in os.listdir("/proc"):
            try:
                with open("/proc/%s/cmdline" % pid, "rb") as f:
                    if b"k/c.off" in f.read():
                        found.append(pid)
            except OSError:
                pass
        return found

    # the process of c.off dies with the batch
    for _ in range(100):
        if not processes_of_c():
            break
        time.sleep(0.02)
    check(not processes_of_c(), "the process of c.off outlived the killed batch")
    left = sorted(f for f in os.listdir(out))
    # a kill that comes while c.off writes its outputs (a loaded machine
    # is slow to see b finished) leaves their hidden temporary files, which
    # nothing can remove on SIGKILL: the rerun must
    temporary = [f for f in left if re.fullmatch(r"\.c\.off\.(json|seg|png|ply|off)\.tmp[0-9_]+", f)]
    left = [f for f in left if f not in temporary]
    check(left == ["a.off.json", "a.off.seg", "b.off.json", "b.off.seg"],
          "after the kill the output folder should hold a and b only (no summary, nothing of c): %s" % left)
    finished = {f: stamp(os.path.join("kout", f)) for f in left}

    os.remove(os.path.join(folder, "c.off"))
    torus(os.path.join(folder, "c.off"), 2.5, 0.5, 9, 9)
    batch(*args[2:], expect_rc=0)
    table = {r["mesh"]: r for r in rows("kout")}
    check([table[c + ".off"]["skipped"] for c in "abcd"] == [True, True, False, False],
          "rerun after the kill: skipped %s, expected a and b only" % {m: r["skipped"] for m, r in table.items()})
    check(all(r["status"] == "ok" for r in table.values()), "rerun after the kill: %s" % table)
    check(all(stamp(os.path.join("kout", f)) == s for f, s in finished.items()),
          "the outputs of a and b were written again by the rerun")
    check(not any(os.path.exists(os.path.join(out, f)) for f in temporary),
          "the rerun left the killed batch's temporary files of c.off: %s" % temporary)
    check(table["a.off"]["seconds"] > 0, "a skipped mesh keeps the seconds of its computation")

    def skipped():
        return {r["mesh"][0]: r["skipped"] for r in rows("kout")}

    batch(*args[2:], expect_rc=0)
    check(skipped() == dict.fromkeys("abcd", True), "a third run should skip everything: %s" % skipped())
    # a new modification time, same content: still finished (content hash)
    os.utime(os.path.join(folder, "a.off"), ns=(time.time_ns(), time.time_ns() + 5 * 10**9))
    # b changed; the JSON report of c lost its batch record (a kill between the
    # report and the record); the labels of d truncated
    torus(os.path.join(folder, "b.off"), 2.0, 0.7, 11, 8)
    with open(os.path.join(out, "c.off.json")) as f:
        report = json.load(f)
    del report["batch"]
    with open(os.path.join(out, "c.off.json"), "w") as f:
        json.dump(report, f)
    with open(os.path.join(out, "d.off.seg"), "r+") as f:
        f.truncate(10)
    batch(*args[2:], expect_rc=0)
    check(skipped() == {"a": True, "b": False, "c": False, "d": False},
          "after touching a, changing b, c's record lost, d's labels cut: %s" % skipped())
    # other options: everything again; --threads and --jobs are not options of the result
    batch(*args[2:], "--jobs", "2", "--threads", "1", expect_rc=0)
    check(skipped() == dict.fromkeys("abcd", True), "--jobs/--threads changed: should skip everything: %s" % skipped())
    batch(*args[2:-1], "4", expect_rc=0)
    check(skipped() == dict.fromkeys("abcd", False), "--k 4 after --k 3: should redo everything: %s" % skipped())
    check(all(r["segments"] == 4 for r in rows("kout")), "--k 4: %s" % rows("kout"))
    batch(*args[2:-1], "4", "--force", expect_rc=0)
    check(skipped() == dict.fromkeys("abcd", False), "--force: should redo everything: %s" % skipped())

    # a mesh that takes too long (240,000 faces, several seconds) is stopped by
    # --timeout and recorded; the batch goes on
    torus(os.path.join(folder, "hang.off"), 2.0, 0.5, 600, 200)
    start = time.time()
    p = batch("k/a.off", "k/hang.off", "--out", "tout", "--k", "3", "--timeout", "1", expect_rc=1)
    table = {r["mesh"]: r for r in rows("tout")}
    check(table["a.off"]["status"] == "ok" and table["hang.off"]["status"] == "error" and
          "--timeout of 1.000 s" in table["hang.off"]["error"], "--timeout: %s" % table)
    check(time.time() - start < 30, "--timeout 1 took %.1f s" % (time.time() - start))
    leftovers = [f for f in os.listdir(os.path.join(WORK, "tout")) if f.startswith("hang")]
    check(leftovers == [], "a mesh stopped by --timeout left %s" % leftovers)


def yaml_block(path, key):
    """The literal block scalar (`- |`) following `key:` in a YAML file."""
    lines = open(path).read().split("\n")
    start = next(i for i, l in enumerate(lines) if l.strip() == key + ":")
    assert lines[start + 1].strip() == "- |"
    indent = len(lines[start + 2]) - len(lines[start + 2].lstrip())
    block = []
    for l in lines[start + 2:]:
        if l.strip() and len(l) - len(l.lstrip()) < indent:
            break
        block.append(l[indent:])
    return "\n".join(block)


def test_scripts():
    make_dataset()
    full_run()
    tools = os.path.join(WORK, "bin")
    shutil.rmtree(tools, ignore_errors=True)
    os.makedirs(tools)
    env = dict(os.environ, SPECTRALSEG=TOOL, PATH=tools + os.pathsep + os.environ["PATH"])

    # Slurm: a stand-in sbatch that runs the array tasks (then the merge) here
    with open(os.path.join(tools, "sbatch"), "w") as f:
        f.write("""#!/bin/sh
array=; exports=
while [ $# -gt 0 ]; do
  case "$1" in
    --array=*) array=${1#--array=} ;;
    --export=*) exports=${1#--export=} ;;
    --*) ;;
    *) break ;;
  esac
  shift
done
script=$1; shift
n=$(cat "$0.count" 2>/dev/null || echo 100); n=$((n + 1)); echo $n > "$0.count"
if [ -n "$array" ]; then
  range=${array%%%*}; i=${range%-*}
  while [ "$i" -le "${range#*-}" ]; do
    SLURM_ARRAY_TASK_ID=$i SLURM_CPUS_PER_TASK=1 bash "$script" "$@" >> "$0.log" 2>&1 || echo "task $i: $?" >> "$0.log"
    i=$((i + 1))
  done
else
  for kv in $(echo "${exports#ALL}" | tr ',' ' '); do export "$kv"; done
  bash "$script" "$@" >> "$0.log" 2>&1 || echo "job: $?" >> "$0.log"
fi
echo "$n;cluster"
""")
    os.chmod(os.path.join(tools, "sbatch"), 0o755)
    shutil.rmtree(os.path.join(WORK, "slurm"), ignore_errors=True)
    p = run(["bash", os.path.join(REPO, "scripts/batch/slurm_array.sh"), "3", "slurm", "in", "-r"] + METHOD,
            expect_rc=0, env=env)
    check("array job 101 (3 shards), merge job 102" in p.stdout, "slurm_array.sh: " + p.stdout + p.stderr)
    log = open(os.path.join(tools, "sbatch.log")).read()
    check("batch-merge: 3 shards, 6 meshes" in log, "slurm: the merge job did not merge 3 shards:\n" + log)
    same_result("slurm", "full", "slurm_array.sh")

    # Kubernetes: the pod's shell, run here for each completion index
    job = os.path.join(REPO, "scripts/batch/k8s_indexed_job.yaml")
    text = open(job).read()
    shards = re.search(r'name: SHARDS\s+value: "(\d+)"', text).group(1)
    check(re.search(r"completions: (\d+)", text).group(1) == shards, "k8s: completions differs from SHARDS")
    check("completionMode: Indexed" in text, "k8s: not an Indexed Job")
    script = yaml_block(job, "args").replace("/data/results", "k8s").replace("/data/meshes", "in")
    script = script.replace("--k auto", " ".join(METHOD))
    with open(os.path.join(tools, "spectralseg"), "w") as f:
        f.write('#!/bin/sh\nexec "%s" "$@"\n' % TOOL)
    os.chmod(os.path.join(tools, "spectralseg"), 0o755)
    shutil.rmtree(os.path.join(WORK, "k8s"), ignore_errors=True)
    for i in range(int(shards)):
        run(["sh", "-c", script], expect_rc=0, env=dict(env, JOB_COMPLETION_INDEX=str(i), SHARDS=shards))
    merge = re.search(r'command: \["spectralseg", "batch-merge", "/data/results"\]',
                      open(os.path.join(REPO, "scripts/batch/k8s_merge_job.yaml")).read())
    check(merge is not None, "k8s_merge_job.yaml: not the merge command expected")
    run(["spectralseg", "batch-merge", "k8s"], expect_rc=1, env=env)
    same_result("k8s", "full", "k8s_indexed_job.yaml")
    # a pod whose batch could not run (its input is missing) fails, and is retried
    run(["sh", "-c", script.replace(" in ", " missing ")], expect_rc=1,
        env=dict(env, JOB_COMPLETION_INDEX="0", SHARDS=shards))

    # the Kubernetes files against the Kubernetes API's schema
    for name in ("k8s_indexed_job.yaml", "k8s_merge_job.yaml"):
        for problem in k8s_schema_problems(os.path.join(REPO, "scripts/batch", name)):
            check(False, "%s: %s" % (name, problem))

    # GNU parallel (scripts/setup.sh installs it)
    if check(shutil.which("parallel") is not None, "GNU parallel is not installed (bash scripts/setup.sh installs it)"):
        shutil.rmtree(os.path.join(WORK, "parallel"), ignore_errors=True)
        p = run(["bash", os.path.join(REPO, "scripts/batch/gnu_parallel.sh"), "3", "parallel", "in", "-r"] + METHOD,
                expect_rc=1, env=dict(env, PARALLEL_JOBS="2"))
        same_result("parallel", "full", "gnu_parallel.sh")


def k8s_schema_problems(path):
    """What in a Kubernetes manifest the API's schema does not accept: the
    models of Debian's Kubernetes Python client (python3-kubernetes, generated
    from the API's OpenAPI specification) give each object's fields and their
    types; building the objects checks the required fields and the enums."""
    import yaml
    import kubernetes.client
    problems = []

    def walk(value, type_name, where):
        if type_name.startswith("list["):
            if not isinstance(value, list):
                problems.append("%s: a list expected, got %r" % (where, value))
                return
            for i, v in enumerate(value):
                walk(v, type_name[5:-1], "%s[%d]" % (where, i))
        elif type_name.startswith("dict("):
            if not isinstance(value, dict):
                problems.append("%s: a map expected, got %r" % (where, value))
                return
            for k, v in value.items():
                walk(v, type_name[type_name.index(",") + 1:-1].strip(), "%s.%s" % (where, k))
        elif type_name in ("str", "datetime", "date"):
            if not isinstance(value, str):
                problems.append("%s: a string expected, got %r" % (where, value))
        elif type_name == "int":
            if not isinstance(value, int) or isinstance(value, bool):
                problems.append("%s: an integer expected, got %r" % (where, value))
        elif type_name == "bool":
            if not isinstance(value, bool):
                problems.append("%s: true or false expected, got %r" % (where, value))
        elif type_name != "object":
            model = getattr(kubernetes.client, type_name)
            if not isinstance(value, dict):
                problems.append("%s: a %s object expected, got %r" % (where, type_name, value))
                return
            fields = {json_name: attr for attr, json_name in model.attribute_map.items()}
            for k, v in value.items():
                if k not in fields:
                    problems.append("%s.%s: no such field in %s" % (where, k, type_name))
                else:
                    walk(v, model.openapi_types[fields[k]], "%s.%s" % (where, k))

    for doc in yaml.safe_load_all(open(path)):
        if doc is None:
            continue
        kind = "V1" + str(doc.get("kind")) if doc.get("apiVersion") in ("v1", "batch/v1") else None
        if kind is None or not hasattr(kubernetes.client, kind):
            problems.append("apiVersion %s, kind %s: not a kind this schema knows" % (doc.get("apiVersion"), doc.get("kind")))
            continue
        walk(doc, kind, doc["kind"])
        try:  # required fields, enums
            kubernetes.client.ApiClient()._ApiClient__deserialize(doc, kind)
        except (ValueError, TypeError) as e:
            problems.append(str(e))
    return problems


class Slurm_cluster:
    """A Slurm cluster of one node on this machine, from Debian's packages: a
    munge daemon with its own key, slurmctld and slurmd on free ports, all
    files in a fresh folder (short: the munge socket's path is limited).
    Commands get the cluster through $SLURM_CONF (env())."""

    def __init__(self):
        import socket
        import tempfile
        self.dir = tempfile.mkdtemp(prefix="spectralseg-slurm-")
        d = self.dir
        for sub in ("munge", "state", "spool", "log"):
            os.makedirs(os.path.join(d, sub))
        os.chmod(os.path.join(d, "munge"), 0o700)
        key = os.path.join(d, "munge", "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o400)
        self.socket = os.path.join(d, "munge", "socket")
        subprocess.run(["munged", "--force", "--key-file=" + key, "--socket=" + self.socket,
                        "--pid-file=" + os.path.join(d, "munge", "pid"), "--log-file=" + os.path.join(d, "log", "munged.log"),
                        "--seed-file=" + os.path.join(d, "munge", "seed")], check=True)
        ports = []
        for _ in range(2):
            s = socket.socket()
            s.bind(("127.0.0.1", 0))
            ports.append(s.getsockname()[1])
            s.close()
        host = socket.gethostname().split(".")[0]
        user = subprocess.run(["id", "-un"], stdout=subprocess.PIPE, text=True, check=True).stdout.strip()
        self.conf = os.path.join(d, "slurm.conf")
        with open(self.conf, "w") as f:
            f.write("""ClusterName=spectralseg-test
SlurmctldHost={host}(127.0.0.1)
SlurmctldPort={p0}
SlurmdPort={p1}
SlurmUser={user}
SlurmdUser={user}
AuthType=auth/munge
AuthInfo=socket={socket}
CredType=cred/munge
StateSaveLocation={d}/state
SlurmdSpoolDir={d}/spool
SlurmctldPidFile={d}/slurmctld.pid
SlurmdPidFile={d}/slurmd.pid
SlurmctldLogFile={d}/log/slurmctld.log
SlurmdLogFile={d}/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
KillWait=5
MinJobAge=3600
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
NodeName={host} NodeAddr=127.0.0.1 CPUs={cpus} RealMemory=2048 State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
""".format(host=host, p0=ports[0], p1=ports[1], user=user, socket=self.socket, d=d, cpus=os.cpu_count()))
        subprocess.run(["slurmctld", "-f", self.conf, "-i"], check=True, env=self.env())
        subprocess.run(["slurmd", "-f", self.conf], check=True, env=self.env())
        deadline = time.time() + 60
        while time.time() < deadline:
            p = subprocess.run(["sinfo", "-h", "-o", "%T"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                               text=True, env=self.env())
            if p.stdout.strip() == "idle":
                return
            time.sleep(0.5)
        raise RuntimeError("the Slurm node did not come up in 60 s:\n" + self.logs())

    def env(self, base=None):
        return dict(base or os.environ, SLURM_CONF=self.conf)

    def logs(self):
        text = ""
        for name in ("slurmctld.log", "slurmd.log", "munged.log"):
            try:
                text += "--- %s\n%s" % (name, open(os.path.join(self.dir, "log", name)).read()[-3000:])
            except OSError:
                pass
        return text

    def jobs(self):
        """Every job the controller knows: id -> its fields (scontrol show job)."""
        p = subprocess.run(["scontrol", "-o", "show", "job"], stdout=subprocess.PIPE, text=True, env=self.env())
        table = {}
        for line in p.stdout.splitlines():
            fields = dict(f.split("=", 1) for f in line.split() if "=" in f)
            if "JobId" in fields:
                table[fields["JobId"]] = fields
        return table

    def wait(self, timeout=180):
        """Until no job is pending or running."""
        deadline = time.time() + timeout
        while time.time() < deadline:
            if all(j["JobState"] not in ("PENDING", "RUNNING", "CONFIGURING", "COMPLETING")
                   for j in self.jobs().values()):
                return True
            time.sleep(0.5)
        return False

    def stop(self):
        subprocess.run(["scontrol", "shutdown"], env=self.env(), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        subprocess.run(["munged", "--stop", "--socket=" + self.socket], stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        for name in ("slurmctld.pid", "slurmd.pid", "munge/pid"):
            for _ in range(50):  # the daemons end within a few seconds
                try:
                    pid = int(open(os.path.join(self.dir, name)).read())
                    os.kill(pid, 0)
                except (OSError, ValueError):
                    break
                time.sleep(0.1)
            else:
                os.kill(pid, signal.SIGKILL)
        shutil.rmtree(self.dir, ignore_errors=True)


def test_slurm():
    for program in ("munged", "slurmctld", "slurmd", "sbatch"):
        if not check(shutil.which(program) is not None,
                     "%s is not installed (bash scripts/setup.sh installs slurm-wlm and munge)" % program):
            return
    make_dataset()
    full_run()
    cluster = Slurm_cluster()
    try:
        slurm_runs(cluster)
    finally:
        if failures:
            print(cluster.logs())
        cluster.stop()


def submitted(p):
    m = re.search(r"array job (\d+) \((\d+) shards\), merge job (\d+)", p.stdout)
    check(m is not None, "slurm_array.sh did not say what it submitted: " + p.stdout + p.stderr)
    return m.groups() if m else (None, None, None)


def slurm_runs(cluster):
    # the array script as a user submits it: the resources of a task given
    # on the command line (the script asks for 4 CPUs and 8 GB by default)
    env = cluster.env(dict(os.environ, SPECTRALSEG=TOOL, SBATCH_OPTIONS="--cpus-per-task=1 --mem=500M"))
    script = os.path.join(REPO, "scripts/batch/slurm_array.sh")
    shutil.rmtree(os.path.join(WORK, "slurm"), ignore_errors=True)
    start = time.time()
    array, shards, merge = submitted(run(["bash", script, "3", "slurm", "in", "-r"] + METHOD, expect_rc=0, env=env))
    check(cluster.wait(), "the Slurm jobs did not end in 180 s")
    print("slurm: array and merge ended in %.1f s" % (time.time() - start), flush=True)
    jobs = cluster.jobs()
    tasks = {j.get("ArrayTaskId"): j for j in jobs.values() if j.get("ArrayJobId") == array}
    check(sorted(tasks) == ["0", "1", "2"], "slurm: array tasks %s, expected 0 1 2" % sorted(tasks))
    # a task whose shard holds a failed mesh exits with 1 (shown by sacct); 0 otherwise
    check(all(j["JobState"] in ("COMPLETED", "FAILED") for j in tasks.values()),
          "slurm: task states %s" % {i: j["JobState"] for i, j in tasks.items()})
    check(jobs.get(merge, {}).get("JobState") == "FAILED" and jobs[merge].get("ExitCode") == "1:0",
          "slurm: the merge job should end with exit code 1 (2 meshes failed): %s" % jobs.get(merge))
    check(jobs.get(merge, {}).get("Dependency") in (None, "(null)") and
          float(time.mktime(time.strptime(jobs[merge]["StartTime"], "%Y-%m-%dT%H:%M:%S"))) >=
          max(time.mktime(time.strptime(j["EndTime"], "%Y-%m-%dT%H:%M:%S")) for j in tasks.values()),
          "slurm: the merge job started before the array ended")
    log = open(os.path.join(WORK, "spectralseg-merge-%s.out" % merge)).read()
    check("batch-merge: 3 shards, 6 meshes" in log, "slurm: the merge job did not merge 3 shards:\n" + log)
    same_result("slurm", "full", "slurm_array.sh")

    # a task cancelled while it segments a large mesh; the same submission
    # again finishes the batch without redoing what was finished
    folder = os.path.join(WORK, "in2")
    shutil.rmtree(folder, ignore_errors=True)
    for name, nu in (("a", 12), ("b", 10), ("d", 11), ("e", 9)):
        torus(os.path.join(folder, name + ".off"), 2.0, 0.5, nu, 8)
    torus(os.path.join(folder, "c.off"), 2.0, 0.5, 600, 200)  # 240,000 faces: several seconds
    shutil.rmtree(os.path.join(WORK, "slurm2"), ignore_errors=True)
    args = ["bash", script, "2", "slurm2", "in2", "-r"] + METHOD
    array, _, merge = submitted(run(args, expect_rc=0, env=env))
    # with 2 shards of a b c d e (sorted), task 0 takes a, c, e and task 1 b, d:
    # once a is written, task 0 segments c
    deadline = time.time() + 120
    def a_finished():
        try:
            with open(os.path.join(WORK, "slurm2", "a.off.json")) as f:
                return "batch" in json.load(f)
        except (OSError, ValueError):
            return False

    while time.time() < deadline and not a_finished():
        time.sleep(0.02)
    task = "0"
    states = {j.get("ArrayTaskId"): j["JobState"] for j in cluster.jobs().values() if j.get("ArrayJobId") == array}
    check(a_finished() and states.get(task) == "RUNNING",
          "slurm: task 0 should be running (on c.off) once a.off is written: %s" % states)
    run(["scancel", "%s_%s" % (array, task)], expect_rc=0, env=env)
    check(cluster.wait(), "slurm: the jobs did not end after the cancel")
    jobs = cluster.jobs()
    cancelled = [j for j in jobs.values() if j.get("ArrayJobId") == array and j.get("ArrayTaskId") == task]
    check(len(cancelled) == 1 and cancelled[0]["JobState"] == "CANCELLED",
          "slurm: the task of c.off should be CANCELLED: %s" % cancelled)
    job_id = ("SLURM_JOB_ID=%s" % cancelled[0]["JobId"]).encode() if cancelled else b"-"
    survivors = []
    for pid in os.listdir("/proc"):
        try:
            if job_id in open("/proc/%s/environ" % pid, "rb").read().split(b"\0"):
                survivors.append(pid)
        except OSError:
            pass
    check(not survivors, "slurm: processes of the cancelled task are still running: %s" % survivors)
    check(jobs.get(merge, {}).get("JobState") == "FAILED", "slurm: the merge should fail with a shard missing")
    finished = sorted(f[:-len(".seg")] for f in os.listdir(os.path.join(WORK, "slurm2")) if f.endswith(".off.seg"))
    check(finished == ["a.off", "b.off", "d.off"], "slurm: after the cancel, finished: %s" % finished)
    os.remove(os.path.join(folder, "c.off"))  # (smaller: the rerun is quick)
    torus(os.path.join(folder, "c.off"), 2.5, 0.5, 9, 9)
    array, _, merge = submitted(run(args, expect_rc=0, env=env))
    check(cluster.wait(), "slurm: the resubmitted jobs did not end")
    check(cluster.jobs().get(merge, {}).get("JobState") == "COMPLETED",
          "slurm: the resubmitted merge: %s" % cluster.jobs().get(merge))
    table = {r["mesh"]: r for r in rows("slurm2")}
    check(sorted(table) == ["a.off", "b.off", "c.off", "d.off", "e.off"] and
          all(r["status"] == "ok" for r in table.values()), "slurm: after the resubmission: %s" % table)
    check(sorted(m for m, r in table.items() if r["skipped"]) == finished,
          "slurm: the resubmission should skip exactly the meshes finished before the cancel (%s): %s"
          % (finished, {m: r["skipped"] for m, r in table.items()}))

os.makedirs(WORK, exist_ok=True)
start = time.time()
{"shards": test_shards, "jobs": test_jobs, "resume": test_resume, "scripts": test_scripts,
 "slurm": test_slurm}[GROUP]()
print("batch %s: %d failures, %.1f s" % (GROUP, len(failures), time.time() - start))
sys.exit(1 if failures else 0)
