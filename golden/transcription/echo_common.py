def cell(label, value, w=20):
    return f" {label:<{w}}{value:>12}"
def line(*cells):
    return "".join(cells).rstrip()
def mat(label, values, w=20):
    return (f" {label:<{w}}" + "".join(f" {v:>12}" for v in values)).rstrip()
def title(t):
    return [t, "-" * len(t), ""]
def banner(btype, mode, runid):
    star = "*" * 120
    box = f"*  Bearing Type = {btype:<12}Program Mode = {mode:<6}Run Id = {runid}"
    return ["ADVANCED DYNAMICS OF ROLLING ELEMENTS", "A Real Time Simulation of Rolling Bearing Performance", "",
            "[Version (ADORE 5.0)]", "", "Copyright Pradeep K Gupta Inc", "", star, box.ljust(119) + "*", star, ""]
MATHEAD = mat("", ["ROLLING ELEM", "OUTER RACE", "INNER RACE", "CAGE", "SHAFT", "HOUSING"], 28)
