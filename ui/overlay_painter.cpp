#include "overlay_painter.h"

#include "view/legend.h"

#include "view/overlay_layers.h"
#include "view/overlay_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <QLinearGradient>
#include <QPainterPath>

#include "heatmap_builder.h"
#include "palette.h"
#include "projector.h"

namespace rcgui {

namespace {

QPen cosmetic(const QColor& c, double width, Qt::PenStyle style = Qt::SolidLine) {
    QPen pen(c, width, style, Qt::RoundCap, Qt::RoundJoin);
    pen.setCosmetic(true);
    return pen;
}

using palette::withAlpha;

// Draws a closed outline twice: a dark halo, then the colour, so it reads on any image.
// An outline holding the whole view has no edge to show: it is only tinted.
void outline(QPainter& p, const QPolygonF& poly, const QColor& c, double width,
             Qt::PenStyle style = Qt::SolidLine, const QColor& fill = Qt::transparent,
             PaintWork* work = nullptr, bool covers = false) {
    if (poly.size() < 2) return;
    if (work) {
        ++work->outlines;
        work->vertices += int(poly.size());
        const double scale = std::sqrt(std::abs(p.transform().determinant()));
        for (int i = 0; i < poly.size(); ++i) {
            const QPointF& a = poly[i];
            work->maxCoord = std::max({work->maxCoord, std::abs(a.x()), std::abs(a.y())});
            work->length += QLineF(a, poly[(i + 1) % poly.size()]).length() * scale;
        }
        if (covers) ++work->covering;
    }
    p.setBrush(Qt::NoBrush);
    if (fill.alpha() > 0) {
        p.setPen(Qt::NoPen);
        p.setBrush(covers ? withAlpha(fill, std::min(fill.alpha(), 25)) : fill);
        p.drawPolygon(poly);
        p.setBrush(Qt::NoBrush);
    }
    if (covers) return;
    p.setPen(cosmetic(QColor(0, 0, 0, 160), width + 2.0));
    p.drawPolygon(poly);
    p.setPen(cosmetic(c, width, style));
    p.drawPolygon(poly);
}

void line(QPainter& p, const QLineF& l, const QColor& c, double width, Qt::PenStyle style = Qt::SolidLine) {
    p.setPen(cosmetic(QColor(0, 0, 0, 160), width + 2.0));
    p.drawLine(l);
    p.setPen(cosmetic(c, width, style));
    p.drawLine(l);
}

QPointF pixelCentre(int pixel, int width) {
    return QPointF(pixel % width + 0.5, pixel / width + 0.5);
}

}  // namespace

void OverlayPainter::paint(QPainter& p, const rc::SessionState& s, const Overlays& o, const rc::Selection& sel,
                           double scale) {
    p.setRenderHint(QPainter::Antialiasing, true);
    work_ = {};
    drawn_.clear();
    lineScale_ = o.lineScale;
    Projector proj(s.scene().camera, s.camera());
    // Everything is clipped to what the widget shows, with a margin so that cut edges
    // stay off screen: no outline is longer than a few times the view's perimeter
    const QRectF device = p.viewport();
    const QRectF visible = p.transform().inverted().mapRect(device);
    const double mx = visible.width() * 0.05 + 1.0, my = visible.height() * 0.05 + 1.0;
    proj.setClip(visible.adjusted(-mx, -my, mx, my));
    pending_ = false;
    if (o.frontier) paintFrontier(p, s, scale, false);
    if (o.misses) paintMisses(p, s, scale, sel);
    if (sel.object >= 0 && sel.object < s.scene().size()) {
        const rc::OverlayShape shape = rc::objectShape(s.scene(), sel.object, proj.core(), rc::ShapeRole::Target);
        outline(p, toQt(shape.outline), palette::kSelection, 3.0 * lineScale_, shape.flat ? Qt::DashLine : Qt::SolidLine,
                shape.flat ? QColor(Qt::transparent) : withAlpha(palette::kSelection, 70), &work_, shape.covers);
    }
    // One ray in focus: the selected one, else the one being traced
    if (auto f = rc::RayFocus::of(s, sel)) {
        if (o.samples) paintSamples(p, s, proj, *f);
        paintFocus(p, s, proj, *f, o);
    }
    if (sel.pixel >= 0 && sel.pixel < s.width() * s.height()) {
        const QPointF c = pixelCentre(sel.pixel, s.width());
        const double half = std::max(0.5, 7.0 / scale);
        outline(p, QPolygonF(QRectF(c.x() - half, c.y() - half, 2 * half, 2 * half)), palette::kSelection,
                2.5 * lineScale_);
    }
    // With a selection in focus, a cross still marks the pixel being traced, so that
    // stepping shows on the image
    const auto& last = s.recorder().lastEvent();
    if ((sel.pixel >= 0 || sel.event >= 0) && last && !s.session().done()) {
        const QPointF c = pixelCentre(last->task.pixel, s.width());
        const double r = std::max(0.7, 9.0 * lineScale_ / scale);
        for (const auto& [colour, width] : {std::pair{QColor(Qt::black), 4.5}, std::pair{palette::kRay, 2.0}}) {
            p.setPen(cosmetic(colour, width * lineScale_));
            p.drawLine(c - QPointF(r, 0), c + QPointF(r, 0));
            p.drawLine(c - QPointF(0, r), c + QPointF(0, r));
        }
    }
    // The queue on top of everything: it is small and it is where the action is
    if (o.frontier) paintFrontier(p, s, scale, true);
    // A layer left events unread: the next paint reads on
    if (pending_ && more_) more_();
}

void OverlayPainter::paintFocus(QPainter& p, const rc::SessionState& s, const Projector& proj,
                                const rc::RayFocus& f, const Overlays& o) {
    if (!(o.hull || o.cylinder)) return;
    // The core makes the shapes (rc::focusShapes); here each role gets its colour and line
    drawn_ = rc::focusShapes(s, f, proj.core(), {o.cylinder, o.hull});
    for (const rc::OverlayShape& shape : drawn_) paintShape(p, shape);
    // The ray's pixel
    const QPointF c = pixelCentre(f.pixel, s.width());
    p.setPen(cosmetic(Qt::black, 2.0));
    p.setBrush(palette::kRay);
    const QTransform t = p.transform();
    const double r = 5.0 / std::max(1e-9, std::sqrt(std::abs(t.determinant())));
    p.drawEllipse(c, r, r);
}

void OverlayPainter::paintShape(QPainter& p, const rc::OverlayShape& shape) {
    using rc::ShapeRole;
    const double px = 1.0 / std::max(1e-9, std::sqrt(std::abs(p.transform().determinant())));  // one screen pixel
    auto closed = [&](const QColor& c, double width, Qt::PenStyle style, int fillAlpha) {
        // A polygon may hold much of the view: dashed, never tinted
        if (shape.flat) style = Qt::DashLine;
        outline(p, toQt(shape.outline), c, width * lineScale_, style,
                shape.flat || fillAlpha == 0 ? QColor(Qt::transparent) : withAlpha(c, fillAlpha), &work_, shape.covers);
    };
    auto segment = [&](const QColor& c, double width, Qt::PenStyle style) {
        const QLineF l(shape.segment->a.x, shape.segment->a.y, shape.segment->b.x, shape.segment->b.y);
        if (l.length() > 0.5) line(p, l, c, width * lineScale_, style);
    };
    auto star = [&](const QColor& c, double radius, int arms) {
        const QPointF centre(shape.point->x, shape.point->y);
        p.setPen(cosmetic(c, arms == 2 ? 2.0 : 3.0));
        for (int k = 0; k < arms; ++k) {
            const double ang = (arms == 2 ? M_PI / 4 : 0.0) + k * M_PI / arms;
            const QPointF d(radius * px * std::cos(ang), radius * px * std::sin(ang));
            p.drawLine(centre - d, centre + d);
        }
    };
    // Each role's colour, width, dash and fill are the core's (rc::roleStyle), as the page's
    const rc::RoleStyle st = rc::roleStyle(shape.role);
    const QColor colour = palette::qt(st.colour);
    if (st.star > 0.0) {
        if (shape.point) star(colour, st.star, st.arms);
    } else if (shape.segment) {
        segment(colour, st.width, st.dashed ? Qt::DashLine : Qt::SolidLine);
    } else {
        closed(colour, st.width, st.dashed ? Qt::DashLine : Qt::SolidLine, st.fill);
    }
}

void OverlayPainter::paintSamples(QPainter& p, const rc::SessionState& s, const Projector& proj, const rc::RayFocus& f) {
    const rc::SampleFan& fan = s.fan(f.pixel);
    const double scale = std::sqrt(std::abs(p.transform().determinant()));
    // The lights' spheres the shadow samples go to
    for (const rc::Sphere& light : fan.lights) {
        if (!(light.r > 0.0)) continue;
        const QPolygonF sil = proj.silhouette(light);
        outline(p, sil, palette::kLight, 2.0 * lineScale_, Qt::DashLine, withAlpha(palette::kLight, 40), &work_,
                proj.covers(sil));
    }
    // Every ray but the eye samples is a segment, clipped to the near plane and the view:
    // one list per colour
    // Segments are cut to the view itself (a few widget pixels over): the outlines' margin
    // of a pixel is thousands of widget pixels at a high zoom, and a stroke costs its length
    const QRectF visible = p.transform().inverted().mapRect(QRectF(p.viewport()));
    const double margin = 4.0 / std::max(1e-9, scale);
    const QRectF view = visible.adjusted(-margin, -margin, margin, margin);
    auto clip = [&](const rc::Vec3& a, const rc::Vec3& b) -> std::optional<QLineF> {
        if (auto l = proj.segment(a, b)) return clipLine(*l, view);
        return std::nullopt;
    };
    std::array<QVector<QLineF>, 4> lines;
    QVector<QLineF> beyond;  // blocked shadow rays: from the blocker on to their light point
    std::array<QVector<QPointF>, 2> dots;  // eye samples: where they meet the image (hit, missed)
    for (const rc::FanRay& r : fan.rays) {
        if (r.kind == rc::RayKind::Primary) {
            if (auto c = proj.point(r.to); c && view.contains(*c)) {
                dots[r.outcome == rc::FanOutcome::Hit ? 0 : 1] << *c;
                ++work_.samples;
            }
            continue;
        }
        if (auto l = clip(r.from, r.to)) {
            lines[int(r.outcome)] << *l;
            ++work_.samples;
            work_.sampleLength += l->length() * scale;
            work_.maxCoord = std::max({work_.maxCoord, std::abs(l->x1()), std::abs(l->y1()), std::abs(l->x2()),
                                       std::abs(l->y2())});
        }
        if (r.outcome == rc::FanOutcome::Blocked)
            if (auto l = clip(r.to, r.aim)) beyond << *l;
    }
    // Solid pens only (a dash pattern costs a stroke per dash). A pen wider than a pixel
    // is stroked as a path and filled by the rasteriser: slow for thousands of long
    // lines. So a large fan is drawn in hairlines (Qt's fast cosmetic stroker), a small
    // one with a dark halo under each line, one path each, so that it reads on any image
    int count = int(beyond.size());
    for (const auto& l : lines) count += int(l.size());
    const bool hairlines = count > rc::SampleFan::kHaloRays;
    const double width = hairlines ? 1.0 : 1.6 * lineScale_;
    p.setBrush(Qt::NoBrush);
    p.setPen(cosmetic(withAlpha(palette::kShadowBlocked, 90), 1.0));
    p.drawLines(beyond);
    if (!hairlines) {
        p.setPen(cosmetic(QColor(0, 0, 0, 150), width + 2.0));
        for (const auto& l : lines)
            for (const QLineF& one : l) p.drawLine(one);  // one short path each
    }
    for (int k = 0; k < 4; ++k) {
        p.setPen(cosmetic(palette::fanOutcome(rc::FanOutcome(k)), width));
        if (hairlines) p.drawLines(lines[k]);
        else
            for (const QLineF& one : lines[k]) p.drawLine(one);
    }
    // The eye samples: dots at their jittered positions in the pixel
    const double r = 3.0 * lineScale_ / std::max(1e-9, scale);
    for (int k = 0; k < 2; ++k) {
        p.setPen(cosmetic(Qt::black, 1.0));
        p.setBrush(k == 0 ? palette::kSampleRay : palette::kSampleMissed);
        for (const QPointF& c : dots[k]) p.drawEllipse(c, r, r);
    }
}

void OverlayPainter::paintFrontier(QPainter& p, const rc::SessionState& s, double scale, bool markers) {
    const rc::FrontierView f = s.session().order().frontier();
    const rc::TraceRecorder& rec = s.recorder();
    const int w = s.width(), h = s.height();
    // Regions of the path being filled: the current one tinted, finished ones only
    // outlined, so that their tints do not stripe the picture
    if (!markers && f.path >= 0) {
        const rc::PathIndex::Update u = regionsIndex_.update(rec, s.serial(), f.path, eventBudget_);
        pending_ = pending_ || !u.complete;
        if (u.rebuilt || !u.pixels.empty() || regionsCurrent_ != f.region || regions_.size() != QSize(w, h)) {
            // The marks of the core (rc::regionLayer), in this viewer's colours
            const std::vector<std::uint8_t> marks = rc::regionLayer(regionsIndex_, w, h, f.region);
            const QRgb colours[3] = {0, qPremultiply(withAlpha(palette::kRegion, rc::colours::kRegionOpacity).rgba()),
                                     qPremultiply(withAlpha(palette::kRegionEdge, rc::colours::kRegionEdgeOpacity).rgba())};
            regions_ = QImage(w, h, QImage::Format_ARGB32_Premultiplied);
            for (int y = 0; y < h; ++y) {
                auto* line = reinterpret_cast<QRgb*>(regions_.scanLine(y));
                for (int x = 0; x < w; ++x) line[x] = colours[marks[std::size_t(y) * std::size_t(w) + std::size_t(x)]];
            }
            regionsCurrent_ = f.region;
        }
        p.save();
        p.setRenderHint(QPainter::SmoothPixmapTransform, scale < 1.0);
        p.drawImage(QRectF(0, 0, w, h), regions_);
        p.restore();
    }
    if (!markers) return;
    // Queued pixels and deferred seeds: squares of a fixed size on screen, larger with
    // large fonts, so that a class sees them from the back row
    const double size = std::max(1.0, 11.0 * lineScale_ / scale);
    auto mark = [&](int px) {
        const QPointF ctr = pixelCentre(px, w);
        p.drawRect(QRectF(ctr.x() - size / 2, ctr.y() - size / 2, size, size));
    };
    p.setPen(cosmetic(Qt::black, 1.5 * lineScale_));
    p.setBrush(palette::kDeferred);
    for (int px : f.deferred) mark(px);
    p.setBrush(palette::kQueued);
    for (int px : f.queued) mark(px);
}

void OverlayPainter::paintMisses(QPainter& p, const rc::SessionState& s, double scale, const rc::Selection& sel) {
    // Misses at the path of the ray in focus (eye, eye/reflection, ...), by reason: one
    // layer of pixels, kept while the render and the path stay (a paint draws one image,
    // however many misses there are)
    const rc::TraceRecorder& rec = s.recorder();
    const int w = s.width(), h = s.height();
    const auto focus = rc::RayFocus::of(s, sel);
    const int path = focus ? focus->node : 0;
    const rc::PathIndex::Update u = missesIndex_.update(rec, s.serial(), path, eventBudget_);
    pending_ = pending_ || !u.complete;
    // A pixel's colour: its miss's reason at the path (rc::missMark), transparent for none
    auto colour = [&](int px) {
        const std::uint8_t reason = rc::missMark(missesIndex_, px);
        return reason == 0 ? QRgb(0) : qPremultiply(palette::missReason(rc::MissReason(reason)).rgba());
    };
    if (u.rebuilt || misses_.size() != QSize(w, h)) {
        misses_ = QImage(w, h, QImage::Format_ARGB32_Premultiplied);
        for (int y = 0; y < h; ++y) {
            auto* line = reinterpret_cast<QRgb*>(misses_.scanLine(y));
            for (int x = 0; x < w; ++x) line[x] = colour(y * w + x);
        }
    } else {
        // Only the pixels whose event changed since the last paint
        for (int px : u.pixels) reinterpret_cast<QRgb*>(misses_.scanLine(px / w))[px % w] = colour(px);
    }
    // Smaller than a screen pixel: blended, so that no miss drops out of the picture
    p.save();
    p.setRenderHint(QPainter::SmoothPixmapTransform, scale < 1.0);
    p.drawImage(QRectF(0, 0, w, h), misses_);
    p.restore();
}

namespace {

/// Swatch and the gap after it, in line heights: a key's text starts this far in.
constexpr double kSwatchLines = 1.3;
/// The swatch itself, in line heights: as wide as a capital, as tall as a lower-case
/// letter, centred on the line
constexpr double kSwatchWidth = 0.8, kSwatchHeight = 0.6, kSwatchTop = (1.0 - kSwatchHeight) / 2.0;
/// Padding inside a box: left and right, top and bottom (widget pixels).
constexpr double kPadX = 8.0, kPadY = 4.0;
/// The font scales tried, largest first, until the boxes fit their column: no smaller
/// than four fifths of the view's font (large fonts stay larger than normal ones).
constexpr std::array<double, 3> kFontScalesToFit{1.0, 0.9, 0.8};
/// A colour bar's strip, in line heights, and the lines under it for its values.
constexpr double kBarStripLines = 0.8, kBarValueLines = 1.0;

/// The sample rays of the pixel in focus, as key lines.
void appendSampleKeys(std::vector<std::pair<QColor, QString>>& keys, const rc::SessionState& s, const rc::RayFocus& focus) {
    const rc::SampleFan& fan = s.fan(focus.pixel);
    const int eye = fan.count(rc::RayKind::Primary), shadow = fan.count(rc::RayKind::Shadow);
    const int other = int(fan.rays.size()) - eye - shadow;
    keys.push_back({Qt::transparent, QString("sample rays of pixel (%1,%2)%3:")
                                         .arg(focus.pixel % s.width()).arg(focus.pixel / s.width())
                                         .arg(fan.cut ? QString(", the first %1").arg(fan.rays.size()) : QString())});
    keys.push_back({palette::kSampleRay, QString("%1 eye sample%2 (dots), %3 reflection/refraction ray%4: hit")
                                             .arg(eye).arg(eye == 1 ? "" : "s").arg(other).arg(other == 1 ? "" : "s")});
    keys.push_back({palette::kSampleMissed, QString("hit nothing (%1)").arg(fan.count(rc::FanOutcome::Missed))});
    keys.push_back({palette::kShadowLit, QString("shadow rays reaching the light (%1 of %2)")
                                             .arg(fan.count(rc::FanOutcome::Lit)).arg(shadow)});
    keys.push_back({palette::kShadowBlocked, QString("shadow rays blocked (%1 of %2)")
                                                 .arg(fan.count(rc::FanOutcome::Blocked)).arg(shadow)});
    double radius = 0.0;
    for (const rc::Sphere& l : fan.lights) radius = std::max(radius, l.r);
    if (radius > 0.0)
        keys.push_back({palette::kLight, QString("light's sphere (r %1), %2 points a hit").arg(radius, 0, 'g', 3).arg(fan.shadowSamples)});
    if (fan.notCast > 0)
        keys.push_back({Qt::transparent, QString("no ray to %1 light points (behind the surface)").arg(fan.notCast)});
}

/// The height of `text` wrapped to `width`, at least one line.
double wrappedHeight(const QFontMetricsF& fm, const QString& text, double width) {
    return std::max(fm.height(), fm.boundingRect(QRectF(0, 0, std::max(1.0, width), 1e6), Qt::TextWordWrap, text).height());
}

/// A box of lines, each indented by `indent`, measured in `fm`.
LegendBlock linesBlock(const QFontMetricsF& fm, const QStringList& lines, double indent) {
    LegendBlock b;
    if (lines.isEmpty()) return b;
    for (const QString& l : lines) b.naturalWidth = std::max(b.naturalWidth, fm.horizontalAdvance(l) + indent + 2 * kPadX + 2);
    b.minWidth = indent + 2 * kPadX + fm.horizontalAdvance("MMMMMM");
    b.height = [fm, lines, indent](double width) {
        double h = 2 * kPadY;
        for (const QString& l : lines) h += wrappedHeight(fm, l, width - indent - 2 * kPadX);
        return h;
    };
    return b;
}

}  // namespace

OverlayPainter::LegendText OverlayPainter::legendText(const rc::SessionState& s, const Overlays& o,
                                                      const rc::Selection& sel) {
    // The caption: scene, cache and order, size, step; then the ray in focus
    LegendText t;
    for (const std::string& line : rc::focusCaption(s, sel)) t.info << QString::fromStdString(line);
    const auto focus = rc::RayFocus::of(s, sel);
    // The key: the core's entries (rc::legendEntries, as the page's), for the shapes drawn
    const rc::LegendShown shown{o.cylinder, o.hull, o.frontier, o.misses};
    coreKeys_.clear();
    const auto addKeys = [&t, this](const std::vector<rc::LegendEntry>& entries) {
        for (const rc::LegendEntry& e : entries)
            t.keys.push_back({e.colour ? palette::qt(*e.colour) : QColor(Qt::transparent), QString::fromStdString(e.text)});
        coreKeys_.insert(coreKeys_.end(), entries.begin(), entries.end());
    };
    addKeys(rc::legendEntries(s, sel, shown, drawn_));
    if (o.samples && focus) appendSampleKeys(t.keys, s, *focus);
    // The miss in focus's cause and the selected pixel (rc::focusEntries)
    addKeys(rc::focusEntries(s, sel, shown, drawn_));
    t.info << extraCaption_;
    // The beam-tree heatmap: the paper's measure of coherence beside it, once the image is complete
    if (heatmap_ == Heatmap::BeamNode && s.session().done()) {
        if (beamSerial_ != s.serial()) {
            beams_ = s.beams().build();
            beamSerial_ = s.serial();
        }
        t.info << QString("beam tree %L1 beams; coherence %2 = average ray-tree size %3 / beam-tree size")
                      .arg(beams_.nodes).arg(beams_.coherence, 0, 'g', 3).arg(beams_.averageRayTreeSize, 0, 'f', 2);
    }
    if (const auto& last = s.recorder().lastEvent(); (sel.pixel >= 0 || sel.event >= 0) && last && !s.session().done())
        t.keys.push_back({palette::kRay, QString("cross: pixel (%1,%2) being traced").arg(last->task.pixel % s.width()).arg(last->task.pixel / s.width())});
    if (!o.legend || !keysShown_) t.keys.clear();
    // A heatmap's colour bar; a scale shared by two renders side by side is drawn once, beside the first
    const bool scaled = heatmap_ == Heatmap::Tests || heatmap_ == Heatmap::VisitOrder || heatmap_ == Heatmap::HitRate;
    lastTop_ = o.legend && scaled ? (heatTop_ > 0.0 ? heatTop_ : HeatmapBuilder::scaleOf(s, heatmap_)) : 0.0;
    t.bar = o.legend && scaled && (keysShown_ || heatTop_ <= 0.0);
    t.barTitle = heatmap_ == Heatmap::Tests     ? "tests per pixel (log scale)"
                 : heatmap_ == Heatmap::HitRate ? "cache hit rate per pixel, all its rays"
                                                : "step of a pixel's first ray";
    if (heatTop_ > 0.0) t.barTitle += ", one scale for both";
    if (o.legend && heatmap_ == Heatmap::HitRate) t.keys.push_back({palette::kNoLookups, "no cache lookups"});
    return t;
}

QString OverlayPainter::barValue(double t) const {
    if (heatmap_ == Heatmap::HitRate) return QString("%1%").arg(int(std::lround(100 * t)));
    const double v = heatmap_ == Heatmap::Tests ? std::expm1(t * std::log1p(lastTop_)) : t * lastTop_;
    return QString::number(v, 'f', v < 10 ? 1 : 0);
}

LegendLayout OverlayPainter::layOut(const QFont& font, const QRectF& area, const QRectF& image, const LegendText& t) {
    // The largest font whose boxes fit the column beside the picture
    LegendLayout layout;
    for (const double scale : kFontScalesToFit) {
        legendFont_ = legendFont(font, scale);
        const QFontMetricsF fm(legendFont_);
        QStringList keyLines;
        for (const auto& k : t.keys) keyLines << k.second;
        const LegendBlock info = linesBlock(fm, t.info, 0.0);
        const LegendBlock key = linesBlock(fm, keyLines, fm.height() * kSwatchLines);
        LegendBlock bar;
        if (t.bar) {
            // Room for three of its values apart, five when wider
            bar.minWidth = 2 * kPadX + 4.0 * fm.horizontalAdvance(barValue(1.0) + "  ");
            bar.naturalWidth = std::max(bar.minWidth, fm.horizontalAdvance(t.barTitle) + 2 * kPadX + 2);
            const QString title = t.barTitle;
            bar.height = [fm, title](double width) {
                return 2 * kPadY + wrappedHeight(fm, title, width - 2 * kPadX) + fm.height() * (kBarStripLines + kBarValueLines) + 4;
            };
        }
        // The room the window keeps beside the picture: the boxes unwrapped, in the view's font
        if (scale == kFontScalesToFit.front())
            legendWidth_ = std::max({info.naturalWidth, key.naturalWidth, bar.naturalWidth}) + 2 * kLegendGap;
        layout = layOutLegend(area, image, info, key, bar);
        if (layout.fits) break;
    }
    return layout;
}

void OverlayPainter::paintLegend(QPainter& p, const rc::SessionState& s, const Overlays& o, const rc::Selection& sel,
                                 const QRectF& area, const QRectF& image) {
    const LegendText t = legendText(s, o, sel);
    layout_ = layOut(p.font(), area, image, t);
    legendKey_ = layout_.key.united(layout_.bar);
    p.save();
    p.setFont(legendFont_);
    // The spacing of the lines as drawn on this device (a screen, a pixmap, an image)
    layout_.lineHeight = QFontMetricsF(p.font()).height();
    p.setRenderHint(QPainter::Antialiasing, true);
    drawInfo(p, t);
    drawKeys(p, t);
    drawBar(p, t);
    p.restore();
}

namespace {

/// A box's dark background; what is drawn in it until restore() stays inside it.
void beginBox(QPainter& p, const QRectF& box) {
    p.save();
    p.setClipRect(box);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0, 0, 0, 175));
    p.drawRoundedRect(box, 6, 6);
    p.setPen(Qt::white);
}

}  // namespace

void OverlayPainter::drawInfo(QPainter& p, const LegendText& t) const {
    const QRectF& box = layout_.info;
    if (box.isEmpty()) return;
    beginBox(p, box);
    const QFontMetricsF fm(p.font());
    const double width = box.width() - 2 * kPadX;
    double y = box.top() + kPadY;
    for (const QString& c : t.info) {
        const double h = wrappedHeight(fm, c, width);
        p.drawText(QRectF(box.left() + kPadX, y, width, h), Qt::AlignVCenter | Qt::AlignLeft | Qt::TextWordWrap, c);
        y += h;
    }
    p.restore();
}

void OverlayPainter::drawKeys(QPainter& p, const LegendText& t) const {
    const QRectF& box = layout_.key;
    if (box.isEmpty()) return;
    beginBox(p, box);
    const QFontMetricsF fm(p.font());
    const double lh = fm.height(), indent = lh * kSwatchLines, width = box.width() - 2 * kPadX - indent;
    double y = box.top() + kPadY;
    for (const auto& [colour, text] : t.keys) {
        if (colour.alpha() > 0) {
            p.setPen(QPen(Qt::black, 1));
            p.setBrush(colour);
            p.drawRect(QRectF(box.left() + kPadX, y + lh * kSwatchTop, lh * kSwatchWidth, lh * kSwatchHeight));
        }
        const double h = wrappedHeight(fm, text, width);
        p.setPen(Qt::white);
        p.drawText(QRectF(box.left() + kPadX + indent, y, width, h), Qt::AlignTop | Qt::AlignLeft | Qt::TextWordWrap, text);
        y += h;
    }
    p.restore();
}

void OverlayPainter::drawBar(QPainter& p, const LegendText& t) const {
    const QRectF& box = layout_.bar;
    if (box.isEmpty()) return;
    beginBox(p, box);
    const QFontMetricsF fm(p.font());
    const double lh = fm.height(), width = box.width() - 2 * kPadX;
    double y = box.top() + kPadY;
    const double titleHeight = wrappedHeight(fm, t.barTitle, width);
    p.drawText(QRectF(box.left() + kPadX, y, width, titleHeight), Qt::AlignTop | Qt::AlignLeft | Qt::TextWordWrap, t.barTitle);
    y += titleHeight;
    const QRectF strip(box.left() + kPadX, y + 2, width, lh * kBarStripLines);
    QLinearGradient g(strip.topLeft(), strip.topRight());
    for (int k = 0; k <= 16; ++k) g.setColorAt(k / 16.0, palette::ramp(k / 16.0));
    p.setPen(QPen(Qt::black, 1));
    p.setBrush(g);
    p.drawRect(strip);
    y = strip.bottom() + 2;
    p.setPen(Qt::white);
    // Five values, or three where five would touch
    const int every = strip.width() < 7.0 * fm.horizontalAdvance(barValue(1.0) + "  ") ? 2 : 1;
    for (int k = 0; k <= 4; k += every) {
        const double at = k / 4.0;
        const QString label = barValue(at);
        const double x = strip.left() + at * strip.width();
        const double wdt = fm.horizontalAdvance(label);
        const double lx = std::clamp(x - wdt / 2, strip.left(), std::max(strip.left(), strip.right() - wdt));
        p.drawText(QRectF(lx, y, wdt + 2, lh * kBarValueLines), Qt::AlignVCenter | Qt::AlignLeft, label);
    }
    p.restore();
}

}  // namespace rcgui
