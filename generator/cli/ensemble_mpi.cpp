/** @file ensemble_mpi.cpp  Ensembles across MPI ranks: chunks handed out by rank 0, results gathered to it. */
#include "cli/ensemble_mpi.hpp"
#include "table_driver.hpp"  // the driver for TableModel, compiled once

#include "output/atomic_file.hpp"

#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace eomgen::cli {

namespace {

using Result = eomgen::MemberResult<eomgen::TableModel>;
constexpr int kTagRequest = 1;  // a worker rank's results of its last chunk, asking for the next
constexpr int kTagChunk = 2;    // rank 0's answer: [first, last) as two uint64, empty when all are handed out

template <class T>
void put(std::string& bytes, const T& value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}
void put_doubles(std::string& bytes, const Eigen::VectorXd& v) {
    put<std::uint64_t>(bytes, std::uint64_t(v.size()));
    bytes.append(reinterpret_cast<const char*>(v.data()), sizeof(double) * std::size_t(v.size()));
}
void put_text(std::string& bytes, const std::string& s) {
    put<std::uint64_t>(bytes, s.size());
    bytes += s;
}

/// Reads back what put() wrote, in the same order.
class Reader {
  public:
    explicit Reader(const std::string& bytes) : p_(bytes.data()), end_(bytes.data() + bytes.size()) {}
    bool done() const { return p_ == end_; }
    template <class T>
    T get() {
        T value;
        take(&value, sizeof value);
        return value;
    }
    Eigen::VectorXd doubles() {
        Eigen::VectorXd v(Eigen::Index(get<std::uint64_t>()));
        take(v.data(), sizeof(double) * std::size_t(v.size()));
        return v;
    }
    std::string text() {
        std::string s(get<std::uint64_t>(), '\0');
        take(s.data(), s.size());
        return s;
    }

  private:
    void take(void* out, std::size_t n) {
        if (std::size_t(end_ - p_) < n) throw std::runtime_error("a rank's results arrived truncated");
        if (n == 0) return;  // an empty vector's data() may be null, and memcpy from or to null is undefined
        std::memcpy(out, p_, n);
        p_ += n;
    }
    const char *p_, *end_;
};

void serialize(const Result& r, std::string& bytes) {
    put<std::uint64_t>(bytes, r.index);
    put<std::uint8_t>(bytes, r.ok ? 1 : 0);
    put(bytes, r.t);
    put(bytes, r.energy);
    put_doubles(bytes, r.x);
    put_doubles(bytes, r.outputs);
    // The sensitivities (empty without --sensitivities): S and Y column-major with their row counts, then dt.
    put<std::uint64_t>(bytes, std::uint64_t(r.S.rows()));
    put_doubles(bytes, Eigen::Map<const Eigen::VectorXd>(r.S.data(), r.S.size()));
    put<std::uint64_t>(bytes, std::uint64_t(r.Y.rows()));
    put_doubles(bytes, Eigen::Map<const Eigen::VectorXd>(r.Y.data(), r.Y.size()));
    put_doubles(bytes, r.dt.transpose());
    put_text(bytes, r.stopped_by);
    put_text(bytes, r.error);
}

Result deserialize(Reader& in) {
    Result r;
    r.index = std::size_t(in.get<std::uint64_t>());
    r.ok = in.get<std::uint8_t>() != 0;
    r.t = in.get<double>();
    r.energy = in.get<double>();
    r.x = in.doubles();
    r.outputs = in.doubles();
    const auto matrix = [&in] {
        const Eigen::Index rows = Eigen::Index(in.get<std::uint64_t>());
        const Eigen::VectorXd v = in.doubles();
        return rows == 0 ? Eigen::MatrixXd() : Eigen::MatrixXd(Eigen::Map<const Eigen::MatrixXd>(v.data(), rows, v.size() / rows));
    };
    r.S = matrix();
    r.Y = matrix();
    r.dt = in.doubles().transpose();
    r.stopped_by = in.text();
    r.error = in.text();
    return r;
}

bool started_by_launcher() {
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
        if (std::getenv(v)) return true;
    return false;
}

/// Rank 0: its own threads and the other ranks take chunks from one counter; results go to the sink in order.
void coordinate(const MpiSession& mpi, std::size_t count, std::size_t chunk, unsigned threads,
                const std::vector<eomgen::Event<eomgen::TableModel::State>>& events, const MemberFunction& member,
                const eomgen::EnsembleOptions& options, const ResultSink& sink) {
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    auto take = [&]() -> std::pair<std::size_t, std::size_t> {
        const std::size_t first = failed ? count : std::min(count, next.fetch_add(chunk));
        return {first, std::min(count, first + chunk)};
    };
    eomgen::InOrder<Result, const ResultSink> in_order(0, sink);
    auto local = [&] {
        try {
            for (auto [first, last] = take(); first < last; std::tie(first, last) = take())
                for (std::size_t i = first; i < last; ++i)
                    in_order.put(i, eomgen::simulate_member<eomgen::TableModel>(options.simulation, events, i, member(i)));
        } catch (...) {
            std::lock_guard<std::mutex> lock(failure_mutex);
            if (!failure) failure = std::current_exception();
            failed = true;
        }
    };
    std::vector<std::thread> pool;
    for (unsigned k = 0; k < threads; ++k) pool.emplace_back(local);
    int active = mpi.size() - 1;
    std::string bytes;
    while (active > 0) {
        int ready = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, kTagRequest, MPI_COMM_WORLD, &ready, &status);
        if (!ready) {
            std::this_thread::sleep_for(std::chrono::microseconds(200));
            continue;
        }
        int size = 0;
        MPI_Get_count(&status, MPI_BYTE, &size);
        bytes.assign(std::size_t(size), '\0');
        MPI_Recv(bytes.data(), size, MPI_BYTE, status.MPI_SOURCE, kTagRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        // The next chunk goes out before this one's results are filed: filing may make this thread the one
        // that writes the table's rows (milliseconds for a chunk), and the worker rank would wait that long.
        const auto [first, last] = take();
        const std::uint64_t range[2] = {first, last};
        MPI_Send(range, 2, MPI_UINT64_T, status.MPI_SOURCE, kTagChunk, MPI_COMM_WORLD);
        if (first >= last) --active;
        try {
            for (Reader in(bytes); !in.done();) {
                Result r = deserialize(in);
                in_order.put(r.index, std::move(r));
            }
        } catch (...) {
            std::lock_guard<std::mutex> lock(failure_mutex);
            if (!failure) failure = std::current_exception();
            failed = true;
        }
    }
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

/// Any other rank: ask for a chunk (sending the last one's results), integrate it on the threads, again.
void work(std::size_t thread_chunk, unsigned threads,
          const std::vector<eomgen::Event<eomgen::TableModel::State>>& events, const MemberFunction& member,
          const eomgen::EnsembleOptions& options) {
    std::string bytes;
    for (;;) {
        MPI_Send(bytes.data(), int(bytes.size()), MPI_BYTE, 0, kTagRequest, MPI_COMM_WORLD);
        std::uint64_t range[2] = {0, 0};
        MPI_Recv(range, 2, MPI_UINT64_T, 0, kTagChunk, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (range[0] >= range[1]) return;
        std::vector<Result> results(std::size_t(range[1] - range[0]));
        eomgen::for_each_index(std::size_t(range[0]), std::size_t(range[1]), threads, thread_chunk,
                               [&](std::size_t i) {
                                   results[i - range[0]] = eomgen::simulate_member<eomgen::TableModel>(
                                       options.simulation, events, i, member(i));
                               });
        bytes.clear();
        for (const Result& r : results) serialize(r, bytes);
    }
}

}  // namespace

MpiSession::MpiSession() {
    if (!started_by_launcher()) return;
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    started_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    MPI_Comm_size(node, &node_size_);
    MPI_Comm_free(&node);
}

unsigned MpiSession::threads(unsigned requested) const {
    if (requested > 0) return requested;
    return std::max(1u, eomgen::thread_count(0) / unsigned(std::max(1, node_size_)));
}

MpiSession::~MpiSession() {
    if (started_) MPI_Finalize();
}

void mpi_ensemble(const MpiSession& mpi, std::size_t count, const MemberFunction& member,
                  const eomgen::EnsembleOptions& options, const ResultSink& sink) {
    eomgen::sim::check_options(options.simulation);
    const auto events = eomgen::sim::until_events<eomgen::TableModel>(options.simulation);
    const unsigned threads = mpi.threads(options.threads);
    // A rank's chunk: about 8 per thread of the whole job, so that ranks balance; at most 1024 members.
    const std::size_t chunk = std::clamp<std::size_t>(count / (8 * std::size_t(mpi.size()) * threads), 1, 1024);
    try {
        if (mpi.rank() == 0)
            coordinate(mpi, count, chunk, threads, events, member, options, sink);
        else
            work(eomgen::chunk_size(chunk, threads), threads, events, member, options);
    } catch (const std::exception& e) {
        std::cerr << "eomgen run: rank " << mpi.rank() << ": " << e.what() << "\n";
        MPI_Abort(MPI_COMM_WORLD, dynamic_cast<const eomgen::output::WriteError*>(&e) ? 3 : 2);
    }
}

}  // namespace eomgen::cli
