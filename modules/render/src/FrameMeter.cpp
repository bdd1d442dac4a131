// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/FrameMeter.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <QOpenGLVersionFunctionsFactory>
#include <QThread>
#include <algorithm>

namespace vv::render {

FrameMeter::FrameMeter() {
    clock_.start();
}

FrameMeter::~FrameMeter() {
    if (QOpenGLContext::currentContext() == context_) {
        release();
    }
}

void FrameMeter::initialize() {
    release();
    context_ = QOpenGLContext::currentContext();
    gl_ = context_ != nullptr
              ? QOpenGLVersionFunctionsFactory::get<QOpenGLFunctions_4_1_Core>(context_)
              : nullptr;
    if (gl_ == nullptr) {
        return;  // wall time only
    }
    softwareGl_ = isSoftwareRenderer(reinterpret_cast<const char*>(gl_->glGetString(GL_RENDERER)));
    if (softwareGl_) {
        return;  // its timer queries tell wall time, not work
    }
    // A zero counter size means the implementation does not really time.
    GLint bits = 0;
    gl_->glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
    if (gl_->glGetError() == GL_NO_ERROR && bits > 0) {
        gl_->glGenQueries(2, queries_.data());
    }
}

void FrameMeter::release() noexcept {
    if (gl_ != nullptr && queries_[0] != 0U && QOpenGLContext::currentContext() == context_) {
        gl_->glDeleteQueries(2, queries_.data());
    }
    queries_ = {};
    gl_ = nullptr;
    context_ = nullptr;
    kept_ = false;
}

void FrameMeter::beginFrame() {
    kept_ = false;
    startNs_ = clock_.nsecsElapsed();
    startCpu_ = cpuTimesNow();
    queried_ = queries_[0] != 0U && QOpenGLContext::currentContext() == context_;
    if (queried_) {
        gl_->glQueryCounter(queries_[0], GL_TIMESTAMP);
    }
}

void FrameMeter::endFrame(bool measure) {
    kept_ = measure;
    gpuMs_.reset();
    if (!queried_ || QOpenGLContext::currentContext() != context_) {
        return;
    }
    gl_->glQueryCounter(queries_[1], GL_TIMESTAMP);
    if (measure) {
        // Waits for the frame's commands to run (as measuring to the swap does).
        GLuint64 begin = 0;
        GLuint64 end = 0;
        gl_->glGetQueryObjectui64v(queries_[0], GL_QUERY_RESULT, &begin);
        gl_->glGetQueryObjectui64v(queries_[1], GL_QUERY_RESULT, &end);
        if (end >= begin) {
            gpuMs_ = static_cast<double>(end - begin) / 1e6;
        }
    }
}

std::optional<FrameMeasurement> FrameMeter::atSwap() {
    if (!kept_) {
        return std::nullopt;
    }
    kept_ = false;
    FrameMeasurement frame;
    frame.wallMilliseconds = static_cast<double>(clock_.nsecsElapsed() - startNs_) / 1e6;
    const std::optional<CpuTimes> now = cpuTimesNow();
    if (startCpu_ && now) {
        frame.processCpuMilliseconds = now->processMilliseconds - startCpu_->processMilliseconds;
        frame.threadCpuMilliseconds = now->threadMilliseconds - startCpu_->threadMilliseconds;
    }
    frame.gpuMilliseconds = gpuMs_;
    frame.cores = std::max(QThread::idealThreadCount(), 1);
    frame.softwareGl = softwareGl_;
    return frame;
}

}  // namespace vv::render
