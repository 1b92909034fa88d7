// event_evaluate's report: DIR/metrics.csv (every key for every method), DIR/report.md with its pictures, and a
// line on stdout.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_EVALUATION_REPORT_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_EVALUATION_REPORT_HPP

#include "sample_evaluation.hpp"
#include "sample_evaluation_pictures.hpp"
#include "sample_pictures.hpp"

#include <fstream>
#include <iostream>
#include <sstream>

namespace sample_evaluation {

/** What was evaluated, and how, for the report's text. */
struct EvaluationReport
{
    std::string method, source, output, filter;  // filter: empty without --filter
    double windowMs = 0, seconds = 0;  // seconds: the method's own time
    bool disparities = false, lifetimes = false;  // what the method estimates
};

/** Writes the report of @p acc; @p filterPicture: the last window before and
after the filter, or empty. */
inline void writeEvaluationReport(const EvaluationReport& r, const EvaluationTotals& acc, const Mat& filterPicture)
{
    // Report.
    auto share = [](int64 a, int64 b) { return b > 0 ? 100.0 * (double)a / (double)b : 0.0; };
    const StereoEventScores& scores = acc.scores;
    const int64 candidates = (int64)scores.visibleSignal, estimated = (int64)scores.estimated;
    const int64 leftSignal = (int64)scores.leftSignal, leftVisible = (int64)acc.visible.leftSignal;
    const int64 leftMotion = (int64)acc.motion.leftSignal;
    const double density = scores.density(), within1 = scores.precision(), matchingRate = scores.matchingRate();
    const double mae = scores.meanAbsError(), relDepth = 100 * scores.meanDepthError();
    const double leftWrong = share((int64)(scores.leftEstimated - scores.leftWithin1), leftSignal);
    const double usPerEvent = acc.events ? r.seconds * 1e6 / (double)acc.events : 0;
    std::string lifetimeError = "n/a", precision = "n/a", recall = "n/a";
    if (r.lifetimes)
    {
        if (!acc.lifetimeError.empty())
            lifetimeError = std::to_string(100.0 * acc.lifetimeError.median());
        precision = acc.noiseFlagged ? std::to_string(share(acc.noiseCorrect, acc.noiseFlagged)) : "n/a";
        recall = acc.noiseTrue ? std::to_string(share(acc.noiseCorrect, acc.noiseTrue)) : "n/a (no noise)";
    }
    // Precision at fixed densities, from the ranking by confidence (the most confident first).
    const bool ranked = acc.ranking.estimated > 0 && !acc.ranking.confidenceEstimated.empty();
    const double fullDensity = acc.ranking.density(), atFull = acc.ranking.precision();
    const double at50 = acc.ranking.precisionAtDensity(50), at75 = acc.ranking.precisionAtDensity(75);
    auto percent = [](double v) { return v < 0 ? std::string("n/a") : cv::format("%.1f %%", v); };
    // Every key for every method, "n/a" where the method estimates no disparities (as for lifetimes).
    auto disparityValue = [&](auto value) {
        std::ostringstream text;
        if (r.disparities)
            text << value;
        else
            text << "n/a";
        return text.str();
    };
    std::ofstream csv(r.output + "/metrics.csv");
    csv << "metric,value\n"
        << "events," << acc.events << "\n"
        << "signal_events," << acc.signal << "\n"
        << "non_occluded_signal_events," << candidates << "\n"
        << "events_with_disparity," << disparityValue(estimated) << "\n"
        << "disparity_density_percent," << disparityValue(density) << "\n"
        << "within_1px_percent," << disparityValue(within1) << "\n"
        << "matching_rate_percent," << disparityValue(matchingRate) << "\n"
        << "left_occluded_percent," << disparityValue(share(leftSignal - leftVisible, leftSignal)) << "\n"
        << "matching_rate_visible_percent," << disparityValue(acc.visible.matchingRate()) << "\n"
        << "matching_rate_motion_percent," << disparityValue(acc.motion.matchingRate()) << "\n"
        << "left_wrong_percent," << disparityValue(leftWrong) << "\n"
        << "left_ambiguous_percent," << disparityValue(share(acc.leftAmbiguous, leftSignal)) << "\n"
        << "left_no_counterpart_percent," << disparityValue(share(acc.leftNoCounterpart, leftSignal)) << "\n"
        << "precision_at_50_percent_density," << disparityValue(at50) << "\n"
        << "precision_at_75_percent_density," << disparityValue(at75) << "\n"
        << "unfiltered_density_percent," << disparityValue(fullDensity) << "\n"
        << "precision_at_unfiltered_density," << disparityValue(atFull) << "\n"
        << "mean_abs_disparity_error_px," << disparityValue(mae) << "\n"
        << "relative_depth_error_percent," << disparityValue(relDepth) << "\n"
        << "lifetime_median_relative_error_percent," << lifetimeError << "\n"
        << "noise_precision_percent," << precision << "\n"
        << "noise_recall_percent," << recall << "\n"
        << "events_with_lifetime," << acc.withLifetime << "\n"
        << "events_with_lifetime_left," << acc.withLifetimeCamera[0] << "\n"
        << "events_with_lifetime_right," << acc.withLifetimeCamera[1] << "\n"
        << "time_per_event_us," << usPerEvent << "\n";
    // The filter's figures: signal kept (recall of the motion's events), noise and flicker removed, and the
    // share of signal among the kept events (precision).
    const int64 noiseEvents = acc.noiseTrue;
    const double signalKept = share(acc.filterSignalKept, acc.signal - acc.flicker);
    const double noiseRemoved = share(noiseEvents - acc.filterNoiseKept, noiseEvents);
    const double flickerRemoved = share(acc.flicker - acc.filterFlickerKept, acc.flicker);
    const double keptPrecision = share(acc.filterSignalKept, acc.filterSignalKept + acc.filterNoiseKept + acc.filterFlickerKept);
    const double filterMevPerS = acc.filterSeconds > 0 ? (double)acc.events / acc.filterSeconds * 1e-6 : 0;
    if (!r.filter.empty())
        csv << "filter," << r.filter << "\n"
            << "filter_signal_kept_percent," << signalKept << "\n"
            << "filter_noise_removed_percent," << noiseRemoved << "\n"
            << "flicker_events," << acc.flicker << "\n"
            << "filter_flicker_removed_percent," << (acc.flicker ? std::to_string(flickerRemoved) : "n/a") << "\n"
            << "filter_kept_signal_share_percent," << keptPrecision << "\n"
            << "filter_mev_per_s," << filterMevPerS << "\n";
    // The report shows what the method estimates: disparities, lifetimes (with noise), both, or neither
    // (--method=none, for a filter).
    const bool disparities = r.disparities, lifetimes = r.lifetimes;
    const std::string noiseText = !acc.noiseFlagged && !acc.noiseTrue ? std::string("n/a (no noise, none classified as noise)")
        : (acc.noiseFlagged ? percent(share(acc.noiseCorrect, acc.noiseFlagged)) : std::string("n/a (none classified as noise)"))
          + " / " + (acc.noiseTrue ? percent(share(acc.noiseCorrect, acc.noiseTrue)) : std::string("n/a (no noise)"));
    std::ofstream md(r.output + "/report.md");
    md << "# Evaluation: " << r.method << " on " << r.source << "\n\n"
       << "Windows of " << r.windowMs << " ms, both cameras. "
       << (disparities ? "Disparity metrics over the non-occluded signal events (ground-truth flags)."
                       : "`" + r.method + "` estimates no disparities.")
       << (lifetimes ? " Lifetimes over the signal events, noise over all." : "") << "\n\n"
       << "| metric | value |\n|---|---|\n"
       << "| events (signal / noise) | " << acc.events << " (" << acc.signal << " / " << acc.noiseTrue << ") |\n";
    if (disparities)
        md << "| disparity density (estimated / non-occluded signal) | " << density << " % (" << estimated << " / " << candidates << ") |\n"
           << "| estimated events within 1 px | " << within1 << " % |\n"
           << "| matching rate (left signal events within 1 px of the truth / all left signal events) | " << matchingRate
           << " % (" << (int64)scores.leftWithin1 << " / " << leftSignal << ") |\n"
           << "| ... over the left signal events the right camera sees (" << share(leftSignal - leftVisible, leftSignal)
           << " % are occluded: no matcher can match them) | " << acc.visible.matchingRate() << " % ("
           << (int64)acc.visible.leftWithin1 << " / " << leftVisible << ") |\n"
           << "| ... over the left signal events motion caused (" << share(leftSignal - leftMotion, leftSignal)
           << " % are the flicker's) | " << acc.motion.matchingRate() << " % (" << (int64)acc.motion.leftWithin1
           << " / " << leftMotion << ") |\n"
           << "| left signal events more than 1 px off / rejected (ambiguous) / without a candidate | "
           << leftWrong << " / " << share(acc.leftAmbiguous, leftSignal) << " / "
           << share(acc.leftNoCounterpart, leftSignal) << " % |\n"
           << "| precision (within 1 px) of the most confident estimates at 50 / 75 % density | "
           << (!ranked ? std::string("n/a (" + r.method + " has no confidence)") : percent(at50) + " / " + percent(at75)) << " |\n"
           << "| ... with no rejection (every event's best estimate): density, precision | "
           << (!ranked ? std::string("n/a") : percent(fullDensity) + ", " + percent(atFull)) << " |\n"
           << "| mean absolute disparity error | " << mae << " px |\n"
           << "| mean signed error of the left estimates within 3 px, by third of the columns (left / middle / right) | "
           << acc.signedErrors.text() << " |\n"
           << "| mean relative depth error | " << relDepth << " % |\n";
    if (lifetimes)
        md << "| lifetime median relative error | " << lifetimeError << (acc.lifetimeError.empty() ? "" : " %") << " |\n"
           << "| noise precision / recall | " << noiseText << " |\n"
           << "| events with a lifetime (left / right) | " << acc.withLifetime << " (" << acc.withLifetimeCamera[0]
           << " / " << acc.withLifetimeCamera[1] << ") |\n";
    if (disparities || lifetimes)  // --method=none times nothing
        md << "| time per event | " << usPerEvent << " us |\n";
    if (!r.filter.empty())
        md << "| filter " << r.filter << ": signal kept / noise removed / signal share of the kept events | "
           << signalKept << " / " << noiseRemoved << " / " << keptPrecision << " % (" << noiseEvents << " noise events) |\n"
           << "| filter " << r.filter << ": flicker removed | "
           << (acc.flicker ? cv::format("%.2f %% of %lld flicker events", flickerRemoved, (long long)acc.flicker) : std::string("n/a (no flicker)")) << " |\n"
           << "| filter speed | " << filterMevPerS << " Mev/s |\n";
    if (disparities)
    {
        md << "\n"
           << "![error histogram](disparity_error_histogram.png)\n\n"
           << "![estimate | ground truth](disparity_vs_truth.png)\n";
        if (ranked)
        {
            drawDensityPrecision(acc.ranking, density, within1, r.output + "/density_precision.png",
                                 "precision against density, ranked by confidence (" + r.method + ")");
            md << "\n![density-precision curve](density_precision.png)\n";
        }
        drawHistogram(acc.errorHistogram, r.output + "/disparity_error_histogram.png",
                      "|disparity error| histogram, 0.25 px bins (" + r.method + ")");
    }
    if (lifetimes)
    {
        drawHistogram(acc.lifetimeErrorHistogram, r.output + "/lifetime_error_histogram.png",
                      "|lifetime error| / true lifetime, 2.5 % bins, last bin >= 100 % (" + r.method + ")", "100 %");
        md << "\n![lifetime error histogram](lifetime_error_histogram.png)\n";
    }
    if (disparities)
    {
        // Both on the scale of the disparities the truth holds (0 there: none).
        Mat truth = acc.lastTruth.clone();
        truth.setTo(-1, truth <= 0);
        const Vec2i range = disparityDisplayRange(truth, 0, 255);
        Mat pair;
        hconcat(sampleColourDisparity(acc.lastEstimate, range), sampleColourDisparity(acc.lastTruth, range), pair);
        resize(pair, pair, Size(), 2, 2, INTER_NEAREST);
        imwrite(r.output + "/disparity_vs_truth.png", pair);
    }
    if (!filterPicture.empty())
    {
        imwrite(r.output + "/filter_before_after.png", filterPicture);
        md << "\n![left events of the last window: all | kept by " << r.filter << " (signal ON white, OFF grey, noise red, flicker blue)](filter_before_after.png)\n";
        std::cout << "filter " << r.filter << ": signal kept " << signalKept << " %, noise removed " << noiseRemoved
                  << " % of " << noiseEvents;
        if (acc.flicker)
            std::cout << ", flicker removed " << flickerRemoved << " % of " << acc.flicker;
        std::cout << ", signal share of kept " << keptPrecision << " %, "
                  << filterMevPerS << " Mev/s\n";
    }
    if (disparities)
        std::cout << "density " << density << " %, within 1 px " << within1 << " %, matching rate " << matchingRate
                  << " %, MAE " << mae << " px, ";
    if (lifetimes)
        std::cout << "lifetime median relative error " << lifetimeError << (acc.lifetimeError.empty() ? "" : " %")
                  << ", " << acc.withLifetime << " of " << acc.events << " events with a lifetime, ";
    if (disparities || lifetimes)
        std::cout << usPerEvent << " us/event; ";
    std::cout << "report in " << r.output << "/report.md\n";
}

}  // namespace sample_evaluation

#endif  // OPENCV_EVENT_SAMPLES_SAMPLE_EVALUATION_REPORT_HPP
