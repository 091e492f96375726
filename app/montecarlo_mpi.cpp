// gdnav montecarlo --mpi (compiled only when CMake finds MPI): under `mpirun -np N`, rank r runs shard r+1 of N of
// the batch into the same --out folder (its runs as child processes, --jobs at a time), then sends the metrics.yaml
// of its complete runs to rank 0, which writes those it does not see (no shared file system: tables still complete;
// figures need the runs' run.h5, i.e. a shared --out) and makes the report. Exit code: the worst rank's.
#define OMPI_SKIP_MPICXX 1  // the C API only
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <sstream>

#include <spdlog/spdlog.h>

#include "launch/batch/batch_report.hpp"
#include "config/config.hpp"
#include "metrics/run_record.hpp"
#include "montecarlo.hpp"
#include "framework/lockstep.hpp"

namespace gdnav::cli {

namespace fs = std::filesystem;

namespace {

// "index size\n<size bytes>" for each complete run of the shard.
std::string pack_metrics(const fs::path& dir, const std::vector<std::uint64_t>& runs) {
    std::string out;
    for (const std::uint64_t i : runs) {
        const fs::path f = dir / "runs" / launch::batch::run_dir_name(i) / "metrics.yaml";
        if (!metrics::run_record_complete(f)) continue;
        const std::string text = launch::batch::read_text(f);
        out += std::to_string(i) + " " + std::to_string(text.size()) + "\n" + text;
    }
    return out;
}

// Rank 0: writes the runs another rank sent that its own file system does not show; returns how many.
std::size_t unpack_metrics(const fs::path& dir, const std::string& packed) {
    std::size_t written = 0;
    std::size_t pos = 0;
    while (pos < packed.size()) {
        const std::size_t eol = packed.find('\n', pos);
        if (eol == std::string::npos) break;
        std::istringstream head(packed.substr(pos, eol - pos));
        std::uint64_t index = 0;
        std::size_t size = 0;
        head >> index >> size;
        const std::string text = packed.substr(eol + 1, size);
        pos = eol + 1 + size;
        const fs::path f = dir / "runs" / launch::batch::run_dir_name(index) / "metrics.yaml";
        if (fs::exists(f) && launch::batch::read_text(f) == text) continue;  // shared file system: already there
        fs::create_directories(f.parent_path());
        launch::batch::write_file_atomic(f, text);
        ++written;
    }
    return written;
}

// Every rank's packed metrics, concatenated, at rank 0 (empty elsewhere).
std::string gather_at_root(const std::string& mine, int rank, int size) {
    int len = static_cast<int>(mine.size());
    std::vector<int> lens(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size));
    MPI_Gather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::string all;
    if (rank == 0) {
        int total = 0;
        for (int r = 0; r < size; ++r) {
            offsets[static_cast<std::size_t>(r)] = total;
            total += lens[static_cast<std::size_t>(r)];
        }
        all.resize(static_cast<std::size_t>(total));
    }
    MPI_Gatherv(mine.data(), len, MPI_CHAR, all.data(), lens.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
    return all;
}

}  // namespace

int run_montecarlo_mpi(const McArgs& a, const CliContext& ctx) {
    MPI_Init(nullptr, nullptr);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const launch::batch::Shard shard{static_cast<std::uint64_t>(rank) + 1, static_cast<std::uint64_t>(size)};
    int code = 0;
    std::string packed;
    const fs::path dir = fs::absolute(a.batch.out);
    try {
        code = run_batch_shard(a, ctx, shard);
        packed = pack_metrics(dir, launch::batch::shard_runs(a.batch.first, a.batch.runs, shard));
    } catch (const config::ConfigError& e) {
        spdlog::error("rank {}: {}", rank, e.what());
        code = framework::kExitConfig;
    } catch (const std::exception& e) {
        spdlog::error("rank {}: {}", rank, e.what());
        code = 1;
    }
    const std::string all = gather_at_root(packed, rank, size);
    int worst = 0;
    MPI_Reduce(&code, &worst, 1, MPI_INT, MPI_MAX, 0, MPI_COMM_WORLD);
    if (rank == 0) {
        code = worst;
        const std::size_t sent = unpack_metrics(dir, all);
        if (sent > 0) spdlog::info("montecarlo --mpi: wrote {} runs' metrics.yaml sent by other ranks", sent);
        spdlog::info("montecarlo --mpi: {} ranks done (worst exit code {})", size, worst);
        if (!a.no_report && worst != framework::kExitConfig && worst != framework::kExitInterrupted) {
            launch::batch::ReportOptions ro;
            ro.figures = !a.no_figures;
            const int rc = launch::batch::write_batch_report({dir}, ro);
            if (rc != 0 && code == 0) code = rc;
        }
    }
    MPI_Finalize();
    return code;
}

}  // namespace gdnav::cli
