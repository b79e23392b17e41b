/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Bands of rows finished in any order by many threads reach the
 *            sink in order, whole, once; a failing row or sink ends the
 *            render with its exception, never a hang
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <chrono>
#include <string>
#include <random>
#include <set>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "output/band_flow.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

using namespace sbrt;

namespace {

/// Rows of `cols` pixels whose red channel holds the row number (mod 256),
/// written by `threads` threads with uneven delays.
void write_rows(BandFlow &flow, int rows, int cols, unsigned threads, int failing_row = -1)
{
    for_each_row(0, rows, threads, [&](int row) {
        try {
            Band &band = flow.band_of(row);
            // uneven row costs: later rows of a band often finish first
            std::this_thread::sleep_for(std::chrono::microseconds((row * 7919) % 300));
            if (row == failing_row)
                fail("row ", row, " failed");
            for (int c = 0; c < cols; ++c)
                band.rgb.row(row - band.first_row)[size_t(c) * 3] =
                    uint8_t(row);
            flow.row_done(row);
        }
        catch (const BandWriter::Cancelled &) {
            // as render_rows: the thread that cancelled reports its error
        }
        catch (...) {
            flow.abort();
            throw;
        }
    });
}

} // namespace

TEST(BandFlow, BandsReachTheSinkInOrderWholeAndOnce)
{
    for (int band_rows : {1, 3, 16, 200}) {
        const int rows = 101, cols = 7;
        int next_row = 0, bands = 0;
        bool rows_right = true;
        const BandSink sink = [&](const Band &band) {
            EXPECT_EQ(band.first_row, next_row) << "band rows " << band_rows;
            for (int r = 0; r < band.rows; ++r)
                for (int c = 0; c < cols; ++c)
                    rows_right = rows_right &&
                                 band.rgb.row(r)[size_t(c) * 3] ==
                                     uint8_t(band.first_row + r);
            next_row += band.rows;
            ++bands;
            // a slow sink: the threads run ahead up to the buffers
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        };
        BandWriter writer(sink, 3);
        BandFlow flow(writer, rows, cols, band_rows, Outputs{});
        write_rows(flow, rows, cols, 4);
        writer.finish();
        EXPECT_EQ(next_row, rows);
        EXPECT_EQ(bands, (rows + band_rows - 1) / band_rows);
        EXPECT_EQ(flow.bands(), bands);
        EXPECT_TRUE(rows_right) << "a row was missing or in another band's place";
    }
}

TEST(BandFlow, TheWriterTakesBandsSubmittedOutOfOrderInOrder)
{
    std::vector<int> seen;
    const BandSink sink = [&](const Band &band) { seen.push_back(band.first_row); };
    BandWriter writer(sink, 4);
    std::vector<Band> bands(4);
    for (int b = 0; b < 4; ++b) {
        bands[size_t(b)] = writer.take();
        prepare_band(bands[size_t(b)], b * 5, 5, 2, Outputs{});
    }
    for (int b : {2, 3, 0, 1})
        writer.submit(std::move(bands[size_t(b)]));
    writer.finish();
    EXPECT_EQ(seen, (std::vector<int>{0, 5, 10, 15}));
}

TEST(BandFlow, AFailingRowOrSinkEndsTheRenderWithItsError)
{
    // a row fails while other threads wait for buffers the sink can no
    // longer free (its next band never completes)
    const BandSink ignore = [](const Band &) {};
    for (int failing : {0, 4, 50}) {
        BandWriter writer(ignore, 3);
        BandFlow flow(writer, 120, 5, 1, Outputs{});
        // the failing row's own error, never the cancellation it causes
        try {
            write_rows(flow, 120, 5, 6, failing);
            ADD_FAILURE() << "row " << failing << " failed silently";
        }
        catch (const Error &e) {
            EXPECT_NE(std::string(e.what()).find("row " + std::to_string(failing) + " failed"),
                      std::string::npos)
                << e.what();
        }
    }
    // the sink fails: every thread taking or handing a band learns it
    int taken = 0;
    const BandSink failing_sink = [&](const Band &band) {
        ++taken;
        if (band.first_row >= 6)
            fail("disk full");
    };
    BandWriter writer(failing_sink, 3);
    BandFlow flow(writer, 200, 5, 2, Outputs{});
    try {
        write_rows(flow, 200, 5, 6);
        ADD_FAILURE() << "the sink failed silently";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("disk full"), std::string::npos) << e.what();
    }
    EXPECT_LE(taken, 5);
}

TEST(BandFlow, OneWriterServesFrameAfterFrameWithItsBuffersWarm)
{
    BandWriter writer;
    std::vector<const uint8_t *> first_frame, second_frame;
    const BandSink first = [&](const Band &band) { first_frame.push_back(band.rgb.row(0)); };
    const BandSink second = [&](const Band &band) { second_frame.push_back(band.rgb.row(0)); };
    for (const BandSink *sink : {&first, &second}) {
        const BandFrame frame(writer, *sink, 2);
        for (int b = 0; b < 6; ++b) {
            Band band = writer.take();
            prepare_band(band, b * 4, 4, 8, Outputs{});
            writer.submit(std::move(band));
        }
        writer.finish();
    }
    ASSERT_EQ(first_frame.size(), 6u);
    ASSERT_EQ(second_frame.size(), 6u);
    // no new memory in the second frame: its bands are the first's buffers
    const std::set<const uint8_t *> kept(first_frame.begin(), first_frame.end());
    EXPECT_LE(kept.size(), 2u);
    for (const uint8_t *p : second_frame)
        EXPECT_TRUE(kept.count(p));

    // a frame given up halfway: the sink is not called after it ends, and
    // the next frame runs as usual
    int late_calls = 0, calls = 0;
    {
        const BandSink counted = [&](const Band &) { ++late_calls; };
        const BandFrame frame(writer, counted, 2);
        Band band = writer.take();
        prepare_band(band, 4, 4, 8, Outputs{}); // row 0's band never comes
        writer.submit(std::move(band));
        writer.cancel();
        EXPECT_THROW(writer.take(), BandWriter::Cancelled);
    }
    EXPECT_EQ(late_calls, 0);
    const BandSink count = [&](const Band &) { ++calls; };
    const BandFrame frame(writer, count, 2);
    for (int b = 0; b < 3; ++b) {
        Band band = writer.take();
        prepare_band(band, b * 4, 4, 8, Outputs{});
        writer.submit(std::move(band));
    }
    writer.finish();
    EXPECT_EQ(calls, 3);
}
