// SPDX-License-Identifier: MIT
// SingleProcessCommunicator (rank 0 of 1) and the process's world communicator.
#include "core/communicator.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>

namespace granulab {

namespace {

void requireSelf(int rank, const char* what) {
    if (rank != 0) {
        throw std::logic_error(std::string("SingleProcessCommunicator::") + what + ": rank " +
                               std::to_string(rank) + " does not exist (one process, rank 0)");
    }
}

}  // namespace

void SingleProcessCommunicator::send(int destination, int tag, ByteBuffer data) {
    requireSelf(destination, "send");
    m_queue.push_back(Message{tag, std::move(data)});
}

ByteBuffer SingleProcessCommunicator::receive(int source, int tag) {
    requireSelf(source, "receive");
    const auto it =
        std::find_if(m_queue.begin(), m_queue.end(), [tag](const Message& m) { return m.tag == tag; });
    if (it == m_queue.end()) {
        // With one process nobody else can send it: an MPI receive would block forever.
        throw std::logic_error("SingleProcessCommunicator::receive: no message with tag " +
                               std::to_string(tag) + " was sent (the receive would block forever)");
    }
    ByteBuffer data = std::move(it->data);
    m_queue.erase(it);
    return data;
}

bool SingleProcessCommunicator::probe(int source, int tag) {
    requireSelf(source, "probe");
    return std::any_of(m_queue.begin(), m_queue.end(), [tag](const Message& m) { return m.tag == tag; });
}

std::vector<ByteBuffer> SingleProcessCommunicator::gather(ByteBuffer mine) {
    std::vector<ByteBuffer> all;
    all.push_back(std::move(mine));
    return all;
}

void SingleProcessCommunicator::abort(int status) {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    std::exit(status);
}

namespace {

std::unique_ptr<Communicator>& worldSlot() {
    static std::unique_ptr<Communicator> world = std::make_unique<SingleProcessCommunicator>();
    return world;
}

}  // namespace

Communicator& worldCommunicator() {
    return *worldSlot();
}

void setWorldCommunicator(std::unique_ptr<Communicator> communicator) {
    if (!communicator) communicator = std::make_unique<SingleProcessCommunicator>();
    // The old communicator is destroyed after the new one is installed.
    worldSlot().swap(communicator);
}

}  // namespace granulab
