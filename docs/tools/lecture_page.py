#!/usr/bin/env python3
"""Writes the Lecture page and the tour figures of the algorithm pages from a tour file.

usage: lecture_page.py TOUR OUT_DIR HAVE_PICTURES HAVE_WEB PAGE...

OUT_DIR/lecture_measured.md lists every stop in order: its title, its caption and (when
HAVE_PICTURES is 1) the screenshot the docs build made of it, tour_stop_K.png.
OUT_DIR/tour_PAGE.md holds the stops whose "page" is PAGE, for that page to include;
every PAGE given gets one, empty when no stop names it. When HAVE_WEB is 1 (the docs build
copied the web edition into html/web/), each stop there is also a live figure: the viewer
opened at the stop (web/index.html?tour=NAME&stop=K&embed=1) in an iframe, above its
static screenshot; the Lecture page links each stop to it. A PAGE written NAME=K,K,...
gets the stops numbered K instead (the lesson plan's figures for the board), each linked
to the live viewer when there is one."""
import json
import sys


def escape(text: str) -> str:
    # Doxygen reads Markdown: keep backslashes, '#', '<' and '@' as text
    return text.replace("\\", "\\\\").replace("<", "&lt;").replace("@", "\\@").replace("#", "\\#")


def live(tour_path: str, k: int, stop: dict, frame: bool) -> str:
    """The viewer at stop k: an iframe of the web edition's page (a relative address, so
    the site works opened from file://), or a link to it."""
    name = tour_path.split("/")[-1].removesuffix(".json")
    url = f"web/index.html?tour={name}&amp;stop={k}"
    title = stop["title"].replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;")
    if not frame:
        return f"\\htmlonly\n<p><a href=\"{url}\">Stop {k}, live in the browser</a></p>\n\\endhtmlonly\n\n"
    return ("\\htmlonly\n"
            f"<iframe class=\"live-figure\" src=\"{url}&amp;embed=1\" title=\"Stop {k}, live: {title}\" "
            "loading=\"lazy\"></iframe>\n"
            "<p class=\"live-figure-note\">Live: RayCache's core in WebAssembly, at this stop. Step it "
            "(Ray, Pixel, Next miss, Play), click a pixel, toggle the overlays; As written returns to the stop. "
            f"<a href=\"{url}\">The whole viewer</a>.</p>\n"
            "\\endhtmlonly\n\n")


def figure(tour_path: str, k: int, stop: dict, pictures: bool, web: str = "") -> str:
    command = f"raycache-gui --tour {tour_path} --stop {k} --window 1280x720 --large-fonts"
    # Explicit paragraphs (\\par): an included document's blank lines do not part them
    text = f"\\par\n<b>Stop {k}: {escape(stop['title'])}.</b> {escape(stop['caption'])}\n\n"
    if web:
        text += live(tour_path, k, stop, web == "frame")
    if pictures:
        text += f"\\image html tour_stop_{k:02d}.png \"Stop {k} of the lecture, at 1280x720 with large fonts\"\n\n"
    text += f"\\verbatim\n{command}\n\\endverbatim\n\n"
    return text


def main() -> int:
    tour_file, out, pictures, web, pages = (sys.argv[1], sys.argv[2], sys.argv[3] == "1", sys.argv[4] == "1",
                                            sys.argv[5:])
    with open(tour_file, encoding="utf-8") as f:
        tour = json.load(f)
    tour_path = "tours/" + tour_file.replace("\\", "/").split("/")[-1]
    stops = tour["stops"]
    lines = [f"\\par\nThe tour `{tour_path}`, *{escape(tour.get('title', ''))}*: {len(stops)} stops. "
             f"{escape(tour.get('description', ''))}\n"]
    if not pictures:
        lines.append("This docs build was configured without the GUI, so the stops have no pictures: "
                     "build with Qt 6 (`RAYCACHE_GUI=ON`) and the docs build makes one of each stop.\n")
    for k, stop in enumerate(stops, 1):
        lines.append(figure(tour_path, k, stop, pictures, "link" if web else ""))
    with open(f"{out}/lecture_measured.md", "w", encoding="utf-8") as f:
        f.write("\n\n".join(lines))
    for page in pages:
        if "=" in page:
            page, numbers = page.split("=", 1)
            text = "\\par\nThe stops of the \\ref lecture to show in class, made by the docs build.\n\n"
            text += "".join(figure(tour_path, int(k), stops[int(k) - 1], pictures, "link" if web else "")
                            for k in numbers.split(","))
            with open(f"{out}/tour_{page}.md", "w", encoding="utf-8") as f:
                f.write(text + "\n")
            continue
        mine = [(k, s) for k, s in enumerate(stops, 1) if s.get("page") == page]
        text = ""
        if mine:
            text = ("\\par\nOn a projector: the stop" + ("s" if len(mine) > 1 else "") + " of the \\ref lecture that show" +
                    ("" if len(mine) > 1 else "s") + " this page, made by the docs build.\n\n")
            if not web:
                text += ("The web edition puts a live viewer at each stop here when the docs are built with "
                         "Emscripten installed (`scripts/setup.sh --with-web`).\n\n")
            text += "".join(figure(tour_path, k, s, pictures, "frame" if web else "") for k, s in mine)
        with open(f"{out}/tour_{page}.md", "w", encoding="utf-8") as f:
            f.write(text + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
