# web/test/compare.py: the browser test's comparisons with the CLI: every number of two JSON documents (to a
# relative tolerance, exact matches counted), strings, texts byte for byte, and the numbers a table shows.
from selenium.webdriver.common.by import By


def leaves(x, path=""):
    """(path, value) of every leaf: /intervals/3/mean/0 -> 33102.2."""
    if isinstance(x, dict):
        for k, v in x.items():
            yield from leaves(v, f"{path}/{k}")
    elif isinstance(x, list):
        for i, v in enumerate(x):
            yield from leaves(v, f"{path}/{i}")
    else:
        yield path, x


def number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def g6(x):
    """C's %g, as the CLI's text and the page print a number."""
    return "%g" % x


class Comparison:
    def __init__(self, relative):
        self.relative = relative
        self.numbers = self.exact = self.close = self.texts = 0
        self.failures = []

    def fail(self, what):
        self.failures.append(what)
        print("DIFFERS:", what)

    def json(self, what, ref, mine, skip=(), strings=False, source="CLI"):
        """Every number of the CLI's document `ref` must be in `mine` at the same path and agree; with strings,
        every string too. Keys only the page has are allowed (its CSV text). `source` names the reference."""
        got = dict(leaves(mine))
        for path, v in leaves(ref):
            if path in skip:
                continue
            if path not in got:
                self.fail(f"{what}{path}: the page has no value ({source}: {v!r})")
            elif number(v):
                self.numbers += 1
                w = got[path]
                if not number(w):
                    self.fail(f"{what}{path}: {source} {v!r}, page {w!r}")
                elif v == w:
                    self.exact += 1
                elif abs(v - w) > self.relative * max(abs(v), abs(w)):
                    self.fail(f"{what}{path}: {source} {v!r}, page {w!r}")
                else:
                    self.close += 1
            elif strings or v is None or isinstance(v, bool):
                self.texts += 1
                if got[path] != v:
                    self.fail(f"{what}{path}: {source} {v!r}, page {got[path]!r}")

    def same_text(self, what, ref, mine):
        self.texts += 1
        if ref != mine:
            self.fail(f"{what}: CLI {ref[:200]!r}, page {mine[:200]!r}")

    def shown(self, driver, tbody, rows, columns=None):
        """The page's table cells against the CLI's numbers printed as %g (None: not compared)."""
        cells = [[td.text for td in tr.find_elements(By.CSS_SELECTOR, "th, td")]
                 for tr in driver.find_elements(By.CSS_SELECTOR, f"#{tbody} tr")]
        if len(cells) != len(rows):
            self.fail(f"{tbody}: {len(cells)} rows shown, the CLI has {len(rows)}")
            return
        for shown, ref in zip(cells, rows):
            for k, v in enumerate(ref[: columns or len(ref)]):
                if v is None or not number(v):
                    continue
                self.texts += 1
                text = shown[k].split(" ")[0]
                if text != g6(v):
                    self.fail(f"{tbody} {ref[0]} column {k}: shown {text}, CLI {g6(v)}")

    def report(self):
        return (f"browser test: {self.numbers} numbers compared with the CLI (the Guide's with host_run), {self.exact} equal to the last bit, "
                f"{self.close} within {self.relative:g} "
                f"relative; {self.texts} strings, texts and shown cells; {len(self.failures)} differences")
