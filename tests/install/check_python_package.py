"""tests/install/check_python_package.py SITE KERNELS SOURCE_DIR BUILD_DIR -- an installed symrep package.

Run by tests/install/test_pip.sh (pip install) and test_install.sh (cmake --install) with the
interpreter the module was built for. SITE is the folder the package symrep was installed into,
KERNELS the installed kernel spec folder (PREFIX/share/jupyter/kernels/symrep). Checks that
  - every file of repl/python/symrep (*.py, *.pyi, py.typed, kernelspec/...) is in SITE/symrep,
    with the compiled module and the rule files (symrep/rules);
  - a clean interpreter (isolated: no PYTHONPATH, no user site, not the current folder; sys.path:
    the standard library, SITE, then the system's site directories for numpy; never the build
    tree or the sources) imports symrep from SITE, evaluates a
    statement that needs the rule files, and its __version__ is project(VERSION) of CMakeLists.txt;
  - the kernel spec is installed, runs `python3 -m symrep.kernel -f {connection_file}` and
    names no folder of the source or build tree.
Prints one line per check; exits with 1 at the first failure.
"""
import json
import os
import re
import subprocess
import sys


def fail(message):
    print("check_python_package: FAILED: " + message, file=sys.stderr)
    sys.exit(1)


def main(site, kernels, src, build):
    package = os.path.join(site, "symrep")
    sources = os.path.join(src, "repl", "python", "symrep")
    missing = []
    for folder, dirs, files in os.walk(sources):
        dirs[:] = [d for d in dirs if d != "__pycache__"]
        for f in files:
            if f.endswith(".pyc"):
                continue
            rel = os.path.relpath(os.path.join(folder, f), sources)
            if not os.path.isfile(os.path.join(package, rel)):
                missing.append(rel)
    if missing:
        fail("not installed in %s: %s" % (package, ", ".join(sorted(missing))))
    modules = [f for f in os.listdir(package) if f.startswith("_symrep") and f.endswith(".so")]
    if not modules:
        fail("no compiled module _symrep*.so in " + package)
    if not os.path.isfile(os.path.join(package, "rules", "vector.rules")):
        fail("no rules/vector.rules in " + package)
    print("package: %s (%d files)" % (package, sum(len(f) for _, _, f in os.walk(package))))

    with open(os.path.join(src, "CMakeLists.txt")) as f:
        version = re.search(r"project\(\s*symrep\s+VERSION\s+([0-9.]+)", f.read()).group(1)
    probe = r"""
import os, sys
site = sys.argv[1]
# the standard library, then SITE, then the system's site directories (numpy; a symrep found
# there instead of in SITE fails the check below)
system = [p for p in sys.path if p.endswith(("site-packages", "dist-packages"))]
sys.path[:] = [p for p in sys.path if p not in system] + [site] + system
import symrep
print(os.path.dirname(os.path.dirname(os.path.abspath(symrep.__file__))))
print(symrep.__version__)
print(symrep.version)
s = symrep.Session()
s.eval("vector a, b")
print(s.eval("rewrite(a x (a x b))"))
print(os.environ.get("SYMREP_RULES_DIR"))
"""
    # -I: no PYTHONPATH, no user site, not the current folder
    env = {"PATH": "/usr/bin:/bin", "HOME": os.environ.get("TMPDIR", "/tmp"), "LC_ALL": "C.UTF-8"}
    r = subprocess.run([sys.executable, "-I", "-c", probe, site], capture_output=True, text=True,
                       env=env, cwd="/")
    if r.returncode != 0:
        fail("the installed package does not work:\n" + r.stdout + r.stderr)
    lines = r.stdout.splitlines()
    if os.path.realpath(lines[0]) != os.path.realpath(site):
        fail("symrep was imported from %s, not from %s" % (lines[0], site))
    if lines[1] != version or lines[2] != version:
        fail("__version__ %s, version %s; CMakeLists.txt says %s" % (lines[1], lines[2], version))
    if lines[3] != "(a . b)*a - |a|^2*b":
        fail("rewrite(a x (a x b)) gave " + lines[3])
    if os.path.realpath(lines[4]) != os.path.realpath(os.path.join(package, "rules")):
        fail("the rules were read from %s, not from the package" % lines[4])
    print("import from a clean interpreter: symrep %s, rewrite(a x (a x b)) = %s" % (lines[1], lines[3]))

    spec = os.path.join(kernels, "kernel.json")
    if not os.path.isfile(spec):
        fail("no kernel spec " + spec)
    for f in os.listdir(os.path.join(sources, "kernelspec")):
        if not os.path.isfile(os.path.join(kernels, f)):
            fail("kernel spec file not installed: " + f)
    with open(spec) as f:
        argv = json.load(f)["argv"]
    if os.path.basename(argv[0]) not in ("python3", "python") or argv[-4:] != ["-m", "symrep.kernel", "-f", "{connection_file}"]:
        fail("the kernel spec runs %s" % argv)
    for folder, _, files in os.walk(kernels):
        for f in files:
            with open(os.path.join(folder, f), "rb") as h:
                text = h.read()
            for tree in (src, build, os.path.realpath(src), os.path.realpath(build)):
                if tree.encode() in text:
                    fail("%s names %s" % (os.path.join(folder, f), tree))
    print("kernel spec: %s runs %s" % (kernels, " ".join(argv)))


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    main(*sys.argv[1:])
