#!/usr/bin/env python3
"""The study's questionnaires answered in a real browser (issue 69): headless Chromium, driven by
Selenium, answers NASA-TLX and SURG-TLX (with their pairwise weights) and the SUS through the
pages `raven_study run --questionnaires browser` serves while an autopilot does the trials. It
types an out-of-range rating and skips an item, and is asked again for each; it stops the session
in the middle of a questionnaire and answers it whole after the session resumes; and the answers
in the report's questionnaires.csv are what it typed.

Usage: study_browser_test.py RAVEN_STUDY [--screenshot PNG]; exits 77 (skipped) without
Chromium, its driver or Selenium (scripts/install-deps.sh installs them).
"""

import argparse
import csv
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import unittest
from pathlib import Path

SKIP = 77
try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.common.exceptions import WebDriverException
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import WebDriverWait
except ImportError:
    print("skipped: python3-selenium is not installed (scripts/install-deps.sh)")
    sys.exit(SKIP)

CHROMIUM = shutil.which("chromium")
DRIVER = shutil.which("chromedriver")
PROTOCOL = """study: browser
tasks:
  reach: {kind: targets, count: 1, distance: 0.008, height: 0.002, time_limit: 30}
conditions:
  A: {scheme: m2}
  B: {scheme: m2, divisor: 1500}
trials_per_condition: 1
order: fixed
questionnaires: [nasa-tlx, surg-tlx, sus]
tlx_weights: true
countdown: 0
rest: 0
"""
PAGE_WAIT = 600  # s: a trial runs before its condition's questionnaires open
# What the participant answers, per condition: ratings (TLXs 0..100, SUS 1..5) and, for the TLXs,
# the side chosen in each of the 15 pairs (1 or 2).
ANSWERS = {
    "A": {"nasa-tlx": ([55, 0, 100, 50, 25, 60], [1, 2] * 7 + [1]),
          "surg-tlx": ([5, 10, 15, 20, 25, 30], [2] * 15),
          "sus": ([4, 2, 4, 2, 5, 1, 3, 2, 4, 1], [])},
    "B": {"nasa-tlx": ([70, 35, 40, 45, 90, 95], [1] * 15),
          "surg-tlx": ([100, 0, 50, 55, 60, 65], [2, 1] * 7 + [2]),
          "sus": ([2, 4, 2, 4, 1, 5, 3, 4, 2, 5], [])},
}
TITLES = {"nasa-tlx": "NASA Task Load Index", "surg-tlx": "Surgery Task Load Index",
          "sus": "System Usability Scale"}


def expected_weights(choices):
    """Per item of six, how often the pairs (in the form's order) chose it."""
    pairs = [(i, j) for i in range(6) for j in range(i + 1, 6)]
    weights = [0] * 6
    for (a, b), side in zip(pairs, choices):
        weights[a if side == 1 else b] += 1
    return weights


class Session:
    """`raven_study run` with the pages on a free port, an autopilot at the pad; its output goes
    to run.log, read as it comes for the pages' address."""

    def __init__(self, study, work):
        self.log_file = work / "run.log"
        self.process = subprocess.Popen(
            [study, "run", "--protocol", str(work / "protocol.yaml"), "--out", str(work / "s"),
             "--participant", "P01", "--autopilot", "--questionnaires", "browser", "--port", "0"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, text=True)
        self.url = None
        log = open(self.log_file, "a")
        for line in self.process.stdout:
            log.write(line)
            found = re.search(r"(http://\S+)", line)
            if found:
                self.url = found.group(1)
                break
        log.flush()
        if self.url is None:
            raise AssertionError("raven_study printed no address:\n" + self.log_file.read_text())
        def copy():
            with log:
                log.writelines(self.process.stdout)

        self.copier = threading.Thread(target=copy, daemon=True)
        self.copier.start()

    def wait(self, timeout):
        code = self.process.wait(timeout)
        self.copier.join()
        self.process.stdout.close()
        return code

    def stop(self):
        self.process.send_signal(signal.SIGINT)
        return self.wait(60)

    def kill(self):
        """Ends a session a failed test left waiting for answers."""
        if self.process.poll() is None:
            self.process.kill()
            self.wait(60)


class BrowserQuestionnaires(unittest.TestCase):
    study = None
    screenshot = None

    @classmethod
    def setUpClass(cls):
        options = webdriver.ChromeOptions()
        options.binary_location = CHROMIUM
        for flag in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu",
                     "--window-size=1000,1400"):
            options.add_argument(flag)
        cls.browser = webdriver.Chrome(service=Service(DRIVER), options=options)

    @classmethod
    def tearDownClass(cls):
        cls.browser.quit()

    def open_form(self, url, name):
        """The page at `url` once it shows questionnaire `name` (the board reloads itself)."""
        self.browser.get(url)
        WebDriverWait(self.browser, PAGE_WAIT).until(lambda b: TITLES[name] in b.title)
        return re.search(r"Condition (\w+)\.", self.browser.find_element(By.TAG_NAME, "p").text)[1]

    def fill(self, name, ratings, choices, only=(), skip=None):
        """Types (TLX) or clicks (SUS) the ratings, items numbered from 1: those in `only` when
        given, all but `skip` otherwise; then the pairs' sides."""
        for i, value in enumerate(ratings, start=1):
            if (only and i not in only) or i == skip:
                continue
            if name == "sus":
                self.browser.find_element(By.ID, f"item{i}-{value}").click()
            else:
                field = self.browser.find_element(By.ID, f"item{i}")
                field.clear()
                field.send_keys(str(value))
        for k, side in enumerate(choices, start=1):
            self.browser.find_element(By.ID, f"pair{k}-{side}").click()

    def send(self):
        """Sends the form and waits for the page the server answers with: a new document, which
        has not the mark this one is given (while the browser swaps them, it may not answer)."""
        self.browser.execute_script("document.body.dataset.sent = '1'")
        self.browser.find_element(By.ID, "send").click()
        WebDriverWait(self.browser, 30, ignored_exceptions=(WebDriverException,)).until(
            lambda b: b.execute_script("return document.readyState === 'complete' && "
                                       "document.body.dataset.sent !== '1'"))

    def problem(self, field):
        return self.browser.find_element(By.ID, f"{field}-problem").text

    def answer_condition(self, url, first_time):
        """Answers one condition's three forms; the first time with a rating off the scale and
        a skipped SUS item, each of which must come back marked."""
        condition = None
        for name in ("nasa-tlx", "surg-tlx", "sus"):
            condition = self.open_form(url, name)
            ratings, choices = ANSWERS[condition][name]
            if first_time and name == "nasa-tlx":
                self.fill(name, [150] + ratings[1:], choices)
                self.send()
                self.assertIn("0..100 in steps of 5", self.problem("item1"))
                self.assertEqual(self.browser.find_element(By.ID, "item2").get_attribute("value"),
                                 str(ratings[1]))  # the rest kept
                self.fill(name, ratings, [], only={1})
            elif first_time and name == "sus":
                self.fill(name, ratings, choices, skip=7)
                self.send()
                self.assertEqual(self.problem("item7"), "please answer this one")
                if self.screenshot:
                    self.browser.save_screenshot(self.screenshot)
                self.fill(name, ratings, [], only={7})
            else:
                self.fill(name, ratings, choices)
            self.send()
            self.assertIn("Thank you", self.browser.page_source)
        return condition

    def test_answers_typed_in_the_browser_are_the_answers_kept(self):
        with tempfile.TemporaryDirectory() as tmp:
            work = Path(tmp)
            (work / "protocol.yaml").write_text(PROTOCOL)
            session = Session(self.study, work)
            self.addCleanup(lambda: session.kill())
            self.assertEqual(self.answer_condition(session.url, first_time=True), "A")
            # Condition B: half its first form typed, then the session is stopped (Ctrl-C).
            self.open_form(session.url, "nasa-tlx")
            self.fill("nasa-tlx", ANSWERS["B"]["nasa-tlx"][0], [], only={1, 2, 3})
            self.assertEqual(session.stop(), 130, (work / "run.log").read_text())
            kept = sorted(p.name for p in (work / "s" / "P01" / "questionnaires").iterdir())
            self.assertEqual(kept, ["A_nasa-tlx.json", "A_surg-tlx.json", "A_sus.json"])
            # Resumed: the trials are sealed, so the questionnaires come first, whole.
            session = Session(self.study, work)
            self.assertEqual(self.answer_condition(session.url, first_time=False), "B")
            self.assertEqual(session.wait(PAGE_WAIT), 0, (work / "run.log").read_text())

            report = subprocess.run([self.study, "report", str(work / "s"), "--out",
                                     str(work / "r")], capture_output=True, text=True)
            self.assertEqual(report.returncode, 0, report.stdout + report.stderr)
            with open(work / "r" / "questionnaires.csv", newline="") as f:
                rows = {(r["condition"], r["questionnaire"]): r for r in csv.DictReader(f)}
            self.assertEqual(len(rows), 6)
            for condition, forms in ANSWERS.items():
                for name, (ratings, choices) in forms.items():
                    row = rows[(condition, name)]
                    self.assertEqual(row["participant"], "P01")
                    self.assertEqual([int(a) for a in row["answers"].split()], ratings)
                    weights = [int(w) for w in row["weights"].split()]
                    self.assertEqual(weights, expected_weights(choices) if choices else [])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("study")
    parser.add_argument("--screenshot", help="save the SUS page with its skipped item marked")
    args, rest = parser.parse_known_args()
    if not (CHROMIUM and DRIVER):
        print("skipped: chromium and chromium-driver are not installed (scripts/install-deps.sh)")
        return SKIP
    BrowserQuestionnaires.study = args.study
    BrowserQuestionnaires.screenshot = args.screenshot
    result = unittest.main(argv=[sys.argv[0]] + rest, exit=False).result
    return 0 if result.wasSuccessful() else 1


if __name__ == "__main__":
    sys.exit(main())
