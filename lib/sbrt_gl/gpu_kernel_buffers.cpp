/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The kernel normals' passes' buffers
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_kernel_buffers.hpp"

#include <vector>

#include "shading/kernel_normals.hpp"

namespace sbrt_gl {

void GpuKernelBuffers::bind_image_records(size_t pixels)
{
    if (!image_hits_ || image_hits_->bytes() < pixels * sizeof(sbrt::GpuPixelHit)) {
        image_hits_.emplace(gl_, GL_SHADER_STORAGE_BUFFER, pixels * sizeof(sbrt::GpuPixelHit));
        depths_.emplace(gl_, GL_SHADER_STORAGE_BUFFER, pixels * sizeof(float));
    }
    image_hits_->bind(2);
}

void GpuKernelBuffers::set_kernel(const sbrt::Tracer &tracer, const sbrt::Camera &camera,
                                  const sbrt::Shading &shading, size_t pixels)
{
    const sbrt::KernelNormals kernel(tracer, camera, shading.kernel);
    const std::vector<double> weights =
        shading.smooth > 0 ? sbrt::gaussian_weights(shading.smooth) : std::vector<double>();
    kernel_ = sbrt::make_gpu_kernel(tracer, camera, kernel, weights);
    const std::vector<float> cells = sbrt::make_gpu_kernel_cells(kernel, weights);
    cells_.emplace(gl_, GL_SHADER_STORAGE_BUFFER, cells.size() * sizeof(float), cells.data());
    if (!block_)
        block_.emplace(gl_, GL_UNIFORM_BUFFER, sizeof(sbrt::GpuKernel));
    block_->upload(&kernel_, sizeof kernel_);
    if (smoothing() && (!normals_ || normals_->bytes() < pixels * 16)) {
        normals_.emplace(gl_, GL_SHADER_STORAGE_BUFFER, pixels * 16);
        across_.emplace(gl_, GL_SHADER_STORAGE_BUFFER, pixels * 16);
    }
}

void GpuKernelBuffers::bind() const
{
    block_->bind(2);
    image_hits_->bind(0);
    depths_->bind(1);
    cells_->bind(4);
    if (smoothing()) {
        normals_->bind(3);
        across_->bind(6);
    }
}

void GpuKernelBuffers::set_rows(int first, int count)
{
    kernel_.counts[1] = uint32_t(first);
    kernel_.counts[2] = uint32_t(count);
    block_->upload(&kernel_, sizeof kernel_);
}

} // namespace sbrt_gl
