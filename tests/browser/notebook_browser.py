#!/usr/bin/env python3
"""tests/browser/notebook_browser.py -- examples/notebooks/foucault.ipynb in a real browser (ctest
python.browser; docs/python.md "Notebooks in a browser").

A classic notebook server (Debian's python3-notebook, no token, a free localhost port) with the
build tree's symrep kernel spec in a temporary JUPYTER_PATH; headless Chromium (Debian's
/usr/bin/chromium and /usr/bin/chromedriver) through Selenium opens the notebook, runs all its
cells with the symrep kernel and the page is checked as a reader sees it:
  - every code cell ran (In [n]), no error output; the results are Out[n] (execute_result);
  - the LaTeX results and the markdown's formulas are typeset by MathJax (MathJax elements in
    every LaTeX output, no raw "$\\" source left in the page);
  - the trajectory is an inline image of non-trivial size;
  - the code is highlighted by the kernel's CodeMirror mode (kernelspec/kernel.js);
  - Tab in a new cell opens the completer with the engine's names, Shift-Tab the tooltip with
    the builtin's help.
The executed notebook is then exported with `jupyter nbconvert --to html` and opened from the
file with the browser's network switched off: its formulas are typeset too (MathJax from Debian's
libjs-mathjax, /usr/share/javascript/mathjax: no network needed; issue 32).

A screenshot of the executed notebook is written to BUILD/notebook_foucault.png, and to
docs/figures/notebook_foucault.png with SYMREP_WRITE_SCREENSHOT=1. Without chromium, chromedriver,
Selenium, the notebook server or MathJax the test is skipped (exit 77, ctest shows it as skipped).
Run by hand: PYTHONPATH=build/python /usr/bin/python3 tests/browser/notebook_browser.py
"""
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request

SOURCE_DIR = os.environ.get("SYMREP_SOURCE_DIR",
                            os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
BINARY_DIR = os.environ.get("SYMREP_BINARY_DIR", os.path.join(SOURCE_DIR, "build"))
CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
SKIP = 77
T0 = time.monotonic()


def skip(why):
    print("SKIPPED: the notebook browser test needs %s" % why)
    sys.exit(SKIP)


def check(condition, what):
    if not condition:
        raise AssertionError(what)
    print("ok (%5.1f s): %s" % (time.monotonic() - T0, what.split("\n")[0]))


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(what, predicate, timeout):
    end = time.monotonic() + timeout
    while True:
        value = predicate()
        if value:
            return value
        if time.monotonic() > end:
            raise AssertionError("timed out (%g s) waiting for %s" % (timeout, what))
        time.sleep(0.1)


def start_server(env, folder, port, log):
    cmd = [sys.executable, "-m", "notebook", "--no-browser", "--ip=127.0.0.1", "--port=%d" % port,
           "--port-retries=0", "--NotebookApp.token=", "--NotebookApp.password=",
           "--notebook-dir=%s" % folder]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        cmd.append("--allow-root")  # (CI containers run as root)
    server = subprocess.Popen(cmd, env=env, stdout=log, stderr=subprocess.STDOUT)

    def up():
        if server.poll() is not None:
            log.flush()
            with open(log.name) as f:
                raise AssertionError("the notebook server exited (%d):\n%s" % (server.returncode, f.read()))
        try:
            with urllib.request.urlopen("http://127.0.0.1:%d/api/kernelspecs" % port, timeout=2) as r:
                return json.load(r)
        except OSError:
            return None

    specs = wait_for("the notebook server", up, 60)
    check("symrep" in specs["kernelspecs"], "the server sees the symrep kernel spec")
    return server


def browser(width, height):
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--window-size=%d,%d" % (width, height), "--hide-scrollbars", "--force-device-scale-factor=1",
                "--allow-file-access-from-files"):
        options.add_argument(arg)
    return webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)


# the page's own view of itself, as a reader sees it
PAGE_STATE = """
var cells = Jupyter.notebook.get_cells();
var code = cells.filter(function (c) { return c.cell_type === "code"; });
var text = document.getElementById("notebook-container").innerText;
var latex = Array.from(document.querySelectorAll(".output_latex"));
var imgs = Array.from(document.querySelectorAll(".output_png img"));
return {
  prompts: code.map(function (c) { return c.input_prompt_number; }),
  errors: document.querySelectorAll(".output_error, .output_stderr").length,
  out_prompts: Array.from(document.querySelectorAll(".output_prompt")).map(function (e) {
    return e.innerText.trim(); }).filter(function (t) { return t; }),
  latex: latex.length,
  latex_typeset: latex.filter(function (e) {
    return e.querySelector(".MathJax, .MathJax_Display, .MathJax_CHTML, .MathJax_SVG"); }).length,
  markdown_math: document.querySelectorAll(".text_cell_render .MathJax, .text_cell_render .MathJax_CHTML").length,
  raw_tex: text.indexOf("$\\\\") >= 0 || text.indexOf("\\\\frac") >= 0 || text.indexOf("\\\\left") >= 0,
  images: imgs.map(function (i) { return [i.naturalWidth, i.naturalHeight, i.width, i.height]; }),
  builtins: Array.from(document.querySelectorAll(".CodeMirror span.cm-builtin")).map(function (e) {
    return e.textContent; }),
  keywords: Array.from(document.querySelectorAll(".CodeMirror span.cm-keyword")).map(function (e) {
    return e.textContent; }),
  mode: Jupyter.notebook.codemirror_mode,
  kernel: Jupyter.notebook.kernel && Jupyter.notebook.kernel.name
};
"""

# resolves once MathJax has typeset everything queued so far
MATHJAX_DONE = """
var done = arguments[arguments.length - 1];
if (!window.MathJax || !MathJax.Hub) { done("no MathJax"); return; }
MathJax.Hub.Queue(function () { done(MathJax.version); });
"""


def run_notebook(driver, port, name):
    driver.get("http://127.0.0.1:%d/notebooks/%s" % (port, name))
    wait_for("the symrep kernel", lambda: driver.execute_script(
        "return !!(window.Jupyter && Jupyter.notebook && Jupyter.notebook.kernel &&"
        " Jupyter.notebook.kernel.is_connected() && Jupyter.notebook.kernel.info_reply &&"
        " Jupyter.notebook.kernel.info_reply.status === 'ok')"), 60)
    driver.execute_script("Jupyter.notebook.clear_all_output(); Jupyter.notebook.execute_all_cells();")

    def finished():
        s = driver.execute_script(
            "var k = Jupyter.notebook.kernel; return {busy: Jupyter.notebook.kernel_busy,"
            " prompts: Jupyter.notebook.get_cells().filter(function (c) { return c.cell_type === 'code'; })"
            ".map(function (c) { return c.input_prompt_number; })};")
        return not s["busy"] and all(isinstance(p, int) for p in s["prompts"])

    wait_for("all cells to run", finished, 120)
    driver.set_script_timeout(60)
    return driver.execute_async_script(MATHJAX_DONE)


def check_notebook_page(driver):
    s = driver.execute_script(PAGE_STATE)
    check(s["kernel"] == "symrep", "the notebook runs the symrep kernel")
    check(s["prompts"] == list(range(1, len(s["prompts"]) + 1)), "every code cell ran: In %s" % s["prompts"])
    check(s["errors"] == 0, "no error output")
    check(len(s["out_prompts"]) >= 4 and all(p.startswith("Out[") for p in s["out_prompts"]),
          "results are Out[n]: %s" % s["out_prompts"])
    check(s["latex"] >= 1 and s["latex_typeset"] == s["latex"],
          "every LaTeX result is typeset by MathJax (%d of %d)" % (s["latex_typeset"], s["latex"]))
    check(s["markdown_math"] >= 3, "the markdown's formulas are typeset (%d)" % s["markdown_math"])
    check(not s["raw_tex"], "no raw LaTeX source in the page")
    check(len(s["images"]) == 1 and s["images"][0][0] >= 300 and s["images"][0][1] >= 200
          and s["images"][0][2] >= 300, "an inline plot of non-trivial size: %s" % s["images"])
    check(s["mode"] == "symrep" and "solve" in s["builtins"] and "vector" in s["keywords"],
          "the code is highlighted by the symrep CodeMirror mode (builtins %s..., keywords %s)"
          % (s["builtins"][:3], s["keywords"][:2]))


def check_tab_and_shift_tab(driver):
    """Tab opens the completer with the engine's names, Shift-Tab the tooltip with a builtin's help,
    typed into a new cell (deleted afterwards)."""
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.keys import Keys

    def type_into_new_cell(text):
        driver.execute_script("""
          var nb = Jupyter.notebook, c = nb.insert_cell_at_bottom("code");
          nb.select(nb.ncells() - 1); nb.edit_mode();
          c.set_text(arguments[0]); c.code_mirror.setCursor(0, arguments[0].length); c.code_mirror.focus();""",
                              text)

    def delete_new_cell():
        ActionChains(driver).send_keys(Keys.ESCAPE).perform()
        driver.execute_script("var nb = Jupyter.notebook; nb.command_mode(); nb.delete_cell(nb.ncells() - 1);")

    type_into_new_cell("y := inver")
    ActionChains(driver).send_keys(Keys.TAB).perform()
    names = wait_for("the completer", lambda: driver.execute_script(
        "return Array.from(document.querySelectorAll('.completions select option')).map(function (o) {"
        " return o.value; });"), 20)
    check("inverse" in names and "inverse_laplace" in names, "Tab completes from the engine: %s" % names[:4])
    ActionChains(driver).send_keys(Keys.ESCAPE).perform()
    delete_new_cell()
    type_into_new_cell("inverse(w")
    ActionChains(driver).key_down(Keys.SHIFT).send_keys(Keys.TAB).key_up(Keys.SHIFT).perform()
    tip = wait_for("the tooltip", lambda: driver.execute_script(
        "var t = document.getElementById('tooltip'); return t && t.offsetParent !== null &&"
        " t.querySelector('.tooltiptext').innerText;"), 20)
    check(tip.lstrip().startswith("inverse("), "Shift-Tab shows the help of inverse: %r" % tip[:40])
    delete_new_cell()


def screenshot(driver, path):
    # the whole notebook: the page scrolls inside #site, so the window is made as tall as the notebook
    driver.execute_script("Jupyter.notebook.get_selected_cell().unselect();"
                          " document.getElementById('site').scrollTop = 0;")
    for _ in range(3):  # the window as tall as the notebook (its layout may change with the size)
        missing = driver.execute_script("var s = document.getElementById('site');"
                                        " return s.scrollHeight - s.clientHeight;")
        if missing <= 0:
            break
        size = driver.get_window_size()
        driver.set_window_size(1100, min(size["height"] + missing + 20, 6000))
        time.sleep(0.3)
    driver.save_screenshot(path)
    print("screenshot:", path)


def check_exported_html(driver, notebook):
    html = os.path.splitext(notebook)[0] + ".html"
    # what `jupyter nbconvert --to html NOTEBOOK` runs (its default HTMLExporter), in this process
    import warnings

    from nbconvert import HTMLExporter

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # "No lexer found for language 'symrep'" without the entry point
        page, _ = HTMLExporter().from_filename(notebook)
    with open(html, "w") as f:
        f.write(page)
    check("MathJax" in page, "jupyter nbconvert --to html")
    remote = [u for u in ("https://cdn", "http://cdn", "https://cdnjs", "unpkg.com") if u in page]
    check(not remote, "the exported HTML loads nothing from a CDN %s" % remote)
    # no network: the browser's network is off, and everything it loads must be a local file
    driver.set_network_conditions(offline=True, latency=0, download_throughput=0, upload_throughput=0)
    driver.get("file://" + html)
    version = driver.execute_async_script(MATHJAX_DONE)
    check(version.startswith("2."), "MathJax %s loaded without network" % version)
    s = driver.execute_script("""
      var text = document.body.innerText;
      return {
        math: document.querySelectorAll(".MathJax, .MathJax_Display, .MathJax_CHTML").length,
        errors: document.querySelectorAll(".MathJax_Error, merror").length,
        latex_outputs: document.querySelectorAll(".jp-RenderedLatex, .output_latex").length,
        raw_tex: text.indexOf("$\\\\") >= 0 || text.indexOf("\\\\frac") >= 0 || text.indexOf("\\\\left") >= 0,
        remote: performance.getEntriesByType("resource").map(function (e) { return e.name; })
          .filter(function (n) { return n.indexOf("file://") !== 0; }),
        images: Array.from(document.querySelectorAll("img")).map(function (i) { return i.naturalWidth; })
      };""")
    check(s["latex_outputs"] >= 1 and s["math"] >= s["latex_outputs"] + 3,
          "the exported page's formulas are typeset (%d MathJax elements)" % s["math"])
    check(s["errors"] == 0 and not s["raw_tex"], "no MathJax error, no raw LaTeX source in the exported page")
    check(not s["remote"], "the exported page fetched only local files %s" % s["remote"][:3])
    check(any(w >= 300 for w in s["images"]), "the exported page shows the plot")


def main():
    for path, why in ((CHROMIUM, "chromium (Debian package chromium)"),
                      (CHROMEDRIVER, "chromedriver (Debian package chromium-driver)")):
        if not os.access(path, os.X_OK):
            skip(why)
    import importlib.util

    for module, package in (("selenium", "python3-selenium"), ("notebook", "python3-notebook"),
                            ("nbconvert", "python3-nbconvert")):
        if importlib.util.find_spec(module) is None:
            skip("the Python module %s (Debian package %s)" % (module, package))
    import symrep.kernel  # the build's module (PYTHONPATH=build/python): its absence is a failure
    if not os.path.exists("/usr/share/javascript/mathjax/MathJax.js"):
        skip("MathJax (Debian package libjs-mathjax)")

    start = time.monotonic()
    root = tempfile.mkdtemp(prefix="symrep_browser_")
    server = driver = None
    log = open(os.path.join(root, "server.log"), "w")
    try:
        symrep.kernel.install(prefix=root, build_tree=True)
        env = dict(os.environ, JUPYTER_PATH=os.path.join(root, "share", "jupyter"),
                   JUPYTER_CONFIG_DIR=os.path.join(root, "config"), JUPYTER_DATA_DIR=os.path.join(root, "data"),
                   JUPYTER_RUNTIME_DIR=os.path.join(root, "runtime"), IPYTHONDIR=os.path.join(root, "ipython"))
        folder = os.path.join(root, "notebooks")
        os.makedirs(folder)
        shutil.copy(os.path.join(SOURCE_DIR, "examples", "notebooks", "foucault.ipynb"), folder)
        port = free_port()
        server = start_server(env, folder, port, log)
        driver = browser(1100, 900)
        version = run_notebook(driver, port, "foucault.ipynb")
        check(version.startswith("2."), "the notebook's MathJax %s typeset the page" % version)
        check_notebook_page(driver)
        check_tab_and_shift_tab(driver)
        driver.execute_script("Jupyter.notebook.save_notebook();")
        wait_for("the notebook to be saved", lambda: driver.execute_script(
            "return !Jupyter.notebook.dirty && Jupyter.notebook.last_modified !== undefined;"), 30)
        shots = [os.path.join(BINARY_DIR, "notebook_foucault.png")]
        if os.environ.get("SYMREP_WRITE_SCREENSHOT") == "1":
            shots.append(os.path.join(SOURCE_DIR, "docs", "figures", "notebook_foucault.png"))
        os.makedirs(BINARY_DIR, exist_ok=True)
        screenshot(driver, shots[0])
        for extra in shots[1:]:
            shutil.copy(shots[0], extra)
            print("screenshot:", extra)
        saved = os.path.join(folder, "foucault.ipynb")
        with open(saved) as f:
            cells = json.load(f)["cells"]
        with open(os.path.join(SOURCE_DIR, "examples", "notebooks", "foucault.ipynb")) as f:
            check([c["source"] for c in cells] == [c["source"] for c in json.load(f)["cells"]],
                  "the saved notebook has the cells of examples/notebooks/foucault.ipynb")
        outputs = [o for c in cells for o in c.get("outputs", [])]
        check(any(o["output_type"] == "execute_result" for o in outputs), "the saved notebook has its results")
        check_exported_html(driver, saved)
    except BaseException:
        log.flush()
        with open(log.name) as f:
            print("the notebook server's log:\n" + f.read()[-4000:])
        raise
    finally:
        if driver is not None:
            driver.quit()
        if server is not None:
            server.terminate()
            try:
                server.wait(10)
            except subprocess.TimeoutExpired:
                server.kill()
        log.close()
        shutil.rmtree(root, ignore_errors=True)
    print("the notebook browser test passed in %.1f s" % (time.monotonic() - start))
    return 0


if __name__ == "__main__":
    sys.exit(main())
