"""How good the estimate of the time to the end in the step lines is (doc/output.md, "Run
feedback"): reads gelmpm logs (e.g. the paper suite's, contrib/benchmarks/paper_suite.sh) and, at
the steps where the wall time first passes 10%, 25%, 50% and 75% of the run's, compares the
estimate "end in ~..." with the wall time that was actually still to come. Prints a Markdown
table: estimate / actual remaining (1 is exact, 2 twice too long).

  /usr/bin/python3 contrib/benchmarks/eta_quality.py output/paper_suite/*.log
"""
import re
import sys

LINE = re.compile(r"step\s+(\d+)\s+t/tau_d =.*wall (.+?) \(([\d.e+-]+)%"
                  r"(?:, end in ~(.+?)(?: at dt/t [^)]*)?)?\)")


def seconds(text):
    text = text.strip()
    m = re.fullmatch(r"([\d.]+) s", text)
    if m:
        return float(m.group(1))
    m = re.fullmatch(r"(\d+) min (\d+) s", text)
    if m:
        return 60 * int(m.group(1)) + int(m.group(2))
    m = re.fullmatch(r"(\d+) h (\d+) min", text)
    if m:
        return 3600 * int(m.group(1)) + 60 * int(m.group(2))
    raise ValueError(text)


def main():
    print("| log | steps | wall | at 10% | at 25% | at 50% | at 75% |")
    print("|---|---|---|---|---|---|---|")
    for path in sys.argv[1:]:
        rows = []
        with open(path) as f:
            for line in f:
                m = LINE.search(line)
                if m:
                    rows.append((int(m.group(1)), seconds(m.group(2)),
                                 seconds(m.group(4)) if m.group(4) else None))
        if not rows:
            continue
        total = rows[-1][1]
        cells = []
        for share in (0.1, 0.25, 0.5, 0.75):
            at = next((r for r in rows if r[1] >= share * total and r[2] is not None), None)
            if at is None or total - at[1] <= 0:
                cells.append("—")
            else:
                cells.append(f"{at[2] / (total - at[1]):.2f} (step {at[0]})")
        print(f"| {path.split('/')[-1]} | {rows[-1][0]} | {total:.0f} s | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
